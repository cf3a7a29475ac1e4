"""Terrain geometry: heights and normals of each feature against their closed forms, the union, the loaders."""

import numpy as np
import pytest

from alightsize_sim.terrain import (BOX, FOOT, HEIGHT_FIELD, HEMISPHERE, PLANE, STEP, Box, HeightField, Hemisphere,
                                    Step, Terrain, clearance, features_along, features_at, height, is_plane, pack,
                                    random_feature, surface)

EXACT = 1e-12           # closed forms evaluated in a few flops of values O(1): round-off is ~1e-15


def _normal_fd(packed, x, y, h):
    """Unit normal (-zx, -zy, 1)/|.| from central differences of the height."""
    zx = (height(packed, x + h, y) - height(packed, x - h, y)) / (2 * h)
    zy = (height(packed, x, y + h) - height(packed, x, y - h)) / (2 * h)
    return np.array([-zx, -zy, 1.0]) / np.sqrt(1 + zx * zx + zy * zy)


def test_plain_plane():
    packed = pack(Terrain())
    assert is_plane(packed) and [a.shape for a in packed] == [(0, 5), (0, 3), (0, 7), (0, 6)]
    for x, y in [(0.0, 0.0), (3.0, -7.5), (-1e6, 2e6)]:
        assert surface(packed, x, y) == (0.0, 0.0, 0.0, 1.0)
        assert features_at(packed, x, y) == (PLANE, -1)
    assert clearance(packed, 1.0, 2.0, 0.25) == 0.25
    assert not is_plane(pack(Terrain(hemispheres=[Hemisphere(0, 0, 1)])))


def test_step_raises_its_left_side():
    packed = pack(Terrain(steps=(Step(1.0, 0.0, 90.0, 0.3),)))      # edge x = 1 heading +y: left is x < 1
    assert surface(packed, 0.5, 2.0) == pytest.approx((0.3, 0.0, 0.0, 1.0), abs=EXACT)
    assert surface(packed, 1.5, 2.0) == (0.0, 0.0, 0.0, 1.0)
    assert height(packed, 1.0, -4.0) == pytest.approx(0.3, abs=EXACT)      # the edge: the upper side
    assert features_at(packed, 0.5, 0.0) == (STEP, 0) and features_at(packed, 1.5, 0.0) == (PLANE, -1)
    assert clearance(packed, 0.0, 0.0, 1.0) == pytest.approx(0.7, abs=EXACT)
    back = pack(Terrain(steps=(Step(1.0, 0.0, 270.0, 0.3),)))       # heading -y: left is x > 1
    assert height(back, 1.5, 0.0) == pytest.approx(0.3, abs=EXACT) and height(back, 0.5, 0.0) == 0.0
    assert height(back, 1.0, 9.0) == pytest.approx(0.3, abs=EXACT)


def test_down_step_and_diagonal_step():
    down = pack(Terrain(steps=(Step(0.0, 0.0, 0.0, -0.2),)))         # edge y = 0 heading +x: left (y > 0) lowered
    assert height(down, 0.0, 0.5) == pytest.approx(-0.2, abs=EXACT) and height(down, 0.0, -0.5) == 0.0
    assert height(down, 3.0, 0.0) == 0.0                              # the edge: the upper side
    assert features_at(down, 0.0, 0.5) == (STEP, 0)
    diag = pack(Terrain(steps=(Step(1.0, 1.0, 45.0, 0.1),)))         # left of y = x
    assert height(diag, 0.0, 0.01) == pytest.approx(0.1, abs=EXACT) and height(diag, 0.01, 0.0) == 0.0


def test_steps_add():
    packed = pack(Terrain(steps=(Step(0.0, 0.0, 90.0, 0.1), Step(-1.0, 0.0, 90.0, 0.2))))
    assert height(packed, 0.5, 0.0) == 0.0
    assert height(packed, -0.5, 0.0) == pytest.approx(0.1, abs=EXACT)
    assert height(packed, -1.5, 0.0) == pytest.approx(0.3, abs=EXACT)
    assert features_at(packed, -0.5, 0.0) == (STEP, 0) and features_at(packed, -1.5, 0.0) == (STEP, 1)


def test_hemisphere_height_and_radial_normal():
    """The sphere z = sqrt(r^2 - d^2) with its radial normal up to where its slope reaches FOOT (85 deg), at
    d = r sin(FOOT); its foot beyond is the cone tangent to it there, z = (r / sin(FOOT) - d) tan(FOOT), down to the
    ground at d = r / sin(FOOT); the plane beyond. Both closed forms to round-off."""
    c, r = np.array([0.4, -0.3]), 0.5
    packed = pack(Terrain(hemispheres=(Hemisphere(*c, r),)))
    s, k = np.sin(np.radians(FOOT)), np.cos(np.radians(FOOT))
    rng = np.random.default_rng(1)
    for _ in range(400):
        d = r / s * np.sqrt(rng.uniform(0, 0.999))
        u = np.array([np.cos(t := rng.uniform(0, 2 * np.pi)), np.sin(t)])
        z, *n = surface(packed, *(c + d * u))
        if d <= r * s:
            zc, nc = np.sqrt(r * r - d * d), np.array([*(d * u), np.sqrt(r * r - d * d)]) / r
        else:
            zc, nc = (r / s - d) * s / k, np.array([*(s * u), k])
        assert z == pytest.approx(zc, abs=EXACT)
        assert np.max(np.abs(np.array(n) - nc)) < EXACT and features_at(packed, *(c + d * u)) == (HEMISPHERE, 0)
    assert surface(packed, c[0] + r / s + 1e-12, c[1]) == (0.0, 0.0, 0.0, 1.0)     # beyond the foot: the plane
    assert surface(packed, c[0], c[1] + 0.6) == (0.0, 0.0, 0.0, 1.0)


def test_box_top_sides_and_yaw():
    packed = pack(Terrain(boxes=(Box(1.0, 2.0, 0.6, 0.2, 0.15, 30.0),)))
    u, w = np.array([np.cos(np.radians(30)), np.sin(np.radians(30))]), np.array([-np.sin(np.radians(30)),
                                                                                 np.cos(np.radians(30))])
    c = np.array([1.0, 2.0])
    for a, b, on in [(0.0, 0.0, True), (0.29, 0.09, True), (-0.29, -0.09, True), (0.31, 0.0, False),
                     (0.0, 0.11, False), (0.2, 0.2, False)]:
        z, *n = surface(packed, *(c + a * u + b * w))
        assert (z, *n) == pytest.approx((0.15 if on else 0.0, 0.0, 0.0, 1.0), abs=EXACT)
        assert features_at(packed, *(c + a * u + b * w)) == ((BOX, 0) if on else (PLANE, -1))
    square = pack(Terrain(boxes=(Box(0.0, 0.0, 0.4, 0.2, 0.1, 90.0),)))   # length along y
    assert height(square, 0.1, 0.2) == 0.1 and height(square, 0.2, 0.0) == 0.0   # its edges are the top


def test_union_takes_the_max():
    packed = pack(Terrain(hemispheres=(Hemisphere(0.0, 0.0, 0.5), Hemisphere(0.6, 0.0, 0.4)),
                          boxes=(Box(0.0, 0.0, 2.0, 0.1, 0.3),)))
    for x in np.linspace(-1.2, 1.2, 97):
        for y in (0.0, 0.04, 0.2):
            parts = [np.sqrt(max(0.25 - x * x - y * y, 0.0)), np.sqrt(max(0.16 - (x - 0.6) ** 2 - y * y, 0.0)),
                     0.3 if abs(x) <= 1.0 and abs(y) <= 0.05 else 0.0]
            assert height(packed, x, y) == pytest.approx(max(parts), abs=EXACT)
            kind, index = features_at(packed, x, y)
            if max(parts) - sorted(parts)[1] > EXACT:                  # a clear top (ties go to round-off)
                assert [(HEMISPHERE, 0), (HEMISPHERE, 1), (BOX, 0)][int(np.argmax(parts))] == (kind, index)


def test_features_along_a_track_are_features_at_each_point():
    """The batch lookup used on footpad tracks: each point's (kind, index) as the scalar one gives it, the plane
    included."""
    xy = np.stack(np.meshgrid(np.linspace(-1.2, 1.2, 25), np.linspace(-0.3, 0.3, 7)), axis=-1).reshape(-1, 2)
    for terrain in (Terrain(), Terrain(steps=(Step(0.3, 0.0, 90.0, 0.1),), hemispheres=(Hemisphere(0.0, 0.0, 0.5),),
                                       boxes=(Box(0.6, 0.0, 0.4, 0.2, 0.3),))):
        packed = pack(terrain)
        kinds, indices = features_along(packed, xy)
        assert list(zip(kinds, indices)) == [features_at(packed, x, y) for x, y in xy]


def test_rock_sits_on_a_step():
    packed = pack(Terrain(steps=(Step(0.0, 0.0, 90.0, 0.3),), hemispheres=(Hemisphere(-1.0, 0.0, 0.2),)))
    assert height(packed, -1.0, 0.1) == pytest.approx(0.3 + np.sqrt(0.03), abs=EXACT)
    assert features_at(packed, -1.0, 0.1) == (HEMISPHERE, 0) and features_at(packed, -0.5, 0.0) == (STEP, 0)


def _plane_field(a=0.1, b=-0.25, c=0.4):
    x0, y0, dx, dy = -1.0, 0.5, 0.2, 0.3
    xs, ys = x0 + dx * np.arange(7), y0 + dy * np.arange(5)
    return HeightField(x0, y0, dx, dy, a + b * xs[None, :] + c * ys[:, None]), (a, b, c)


def test_height_field_exact_on_a_planar_grid():
    f, (a, b, c) = _plane_field()
    packed = pack(Terrain(height_field=f))
    normal = np.array([-b, -c, 1.0]) / np.sqrt(1 + b * b + c * c)
    rng = np.random.default_rng(2)
    points = np.column_stack([rng.uniform(-1.0, 0.2, 300), rng.uniform(0.5, 1.7, 300)])
    points = np.vstack([points, [[-1.0, 0.5], [0.2, 1.7], [0.2, 0.5], [-0.6, 1.1]]])   # corners, a grid node
    for x, y in points:
        z, *n = surface(packed, x, y)
        assert abs(z - (a + b * x + c * y)) < EXACT and np.max(np.abs(np.array(n) - normal)) < EXACT
        assert features_at(packed, x, y) == (HEIGHT_FIELD, 0)
    for x, y in [(-1.01, 1.0), (0.21, 1.0), (0.0, 0.49), (0.0, 1.71)]:
        assert surface(packed, x, y) == (0.0, 0.0, 0.0, 1.0) and features_at(packed, x, y) == (PLANE, -1)


def test_height_field_bilinear_in_a_cell():
    z = np.array([[0.0, 1.0], [2.0, 5.0]])                            # z[j, i] at (i dx, j dy)
    packed = pack(Terrain(height_field=HeightField(0.0, 0.0, 2.0, 4.0, z)))
    for fu, fv in [(0.25, 0.5), (0.9, 0.1), (0.0, 1.0)]:
        want = (1 - fu) * (1 - fv) * 0.0 + fu * (1 - fv) * 1.0 + (1 - fu) * fv * 2.0 + fu * fv * 5.0
        assert height(packed, 2.0 * fu, 4.0 * fv) == pytest.approx(want, abs=EXACT)


@pytest.mark.parametrize("h", [1e-5])
def test_normals_match_finite_differences(h):
    # Central differences with step h: truncation h^2 |f'''| / 6 <= 1e-10 x 40 / 6 < 1e-9 on the hemisphere
    # within 0.8 r (|f'''| < 40 /m^2 for r = 0.5), exact on the bilinear field within one cell (linear along each
    # axis); round-off eps |z| / h ~ 1e-11. Normal components agree to 1e-8.
    rock = pack(Terrain(hemispheres=(Hemisphere(0.2, 0.1, 0.5),), steps=(Step(-5.0, 0.0, 90.0, 0.2),)))
    rng = np.random.default_rng(3)
    for _ in range(100):
        d, t = 0.4 * np.sqrt(rng.uniform()), rng.uniform(0, 2 * np.pi)
        x, y = 0.2 + d * np.cos(t), 0.1 + d * np.sin(t)
        assert np.max(np.abs(np.array(surface(rock, x, y)[1:]) - _normal_fd(rock, x, y, h))) < 1e-8
    field = pack(Terrain(height_field=HeightField(0.0, 0.0, 0.1, 0.1, rng.normal(0, 0.05, (6, 8)))))
    for _ in range(100):
        x, y = 0.1 * rng.integers(0, 7) + rng.uniform(0.01, 0.09), 0.1 * rng.integers(0, 5) + rng.uniform(0.01, 0.09)
        assert np.max(np.abs(np.array(surface(field, x, y)[1:]) - _normal_fd(field, x, y, h))) < 1e-8


def test_random_feature_reproducible_and_within_span():
    sizes = dict(step_height=(-0.2, 0.2), radius=(0.05, 0.3), box_size=(0.1, 0.4), box_height=(0.05, 0.2))
    a = [random_feature(np.random.default_rng(7), 1.5, **sizes) for _ in range(2)]
    assert a[0] == a[1]
    rng, kinds = np.random.default_rng(8), set()
    for _ in range(500):
        t = random_feature(rng, 1.5, **sizes)
        (feature,) = t.steps + t.hemispheres + t.boxes
        kinds.add(type(feature))
        assert np.hypot(feature.x, feature.y) <= 1.5
        if isinstance(feature, Step):
            assert -0.2 <= feature.height <= 0.2
        elif isinstance(feature, Hemisphere):
            assert 0.05 <= feature.radius <= 0.3
        else:
            assert 0.1 <= min(feature.length, feature.width) and max(feature.length, feature.width) <= 0.4
    assert kinds == {Step, Hemisphere, Box}
    only = random_feature(np.random.default_rng(9), 2.0, radius=(0.1, 0.2))
    assert len(only.hemispheres) == 1 and not only.steps and not only.boxes
    with pytest.raises(ValueError):
        random_feature(np.random.default_rng(9), 2.0, box_size=(0.1, 0.2))


def test_loaders_round_trip(tmp_path):
    z = np.random.default_rng(4).normal(0, 0.1, (4, 6))
    np.save(tmp_path / "grid.npy", z)
    np.savetxt(tmp_path / "grid.csv", z, delimiter=",", fmt="%.17g", header="heights, m")
    for name in ("grid.npy", "grid.csv"):
        f = HeightField.from_file(tmp_path / name, dx=0.5, dy=0.25, x0=-1.0, y0=2.0)
        assert np.array_equal(f.z, z) and (f.x0, f.y0, f.dx, f.dy) == (-1.0, 2.0, 0.5, 0.25)
        node = height(pack(Terrain(height_field=f)), -1.0 + 2 * 0.5, 2.0 + 3 * 0.25)    # z[j, i] at i = 2, j = 3
        assert node == pytest.approx(z[3, 2], abs=EXACT)
    with pytest.raises(ValueError):
        HeightField.from_file(tmp_path / "grid.txt", 1.0, 1.0)
    with pytest.raises(ValueError):
        HeightField(0.0, 0.0, 1.0, 1.0, np.zeros(5))


def test_one_numba_type_for_every_terrain():
    if not hasattr(height, "signatures"):
        pytest.skip("numba JIT disabled")
    f, _ = _plane_field()
    for t in [Terrain(), Terrain(steps=[Step(0, 0, 10, 0.1)]), Terrain(boxes=[Box(0, 0, 1, 1, 1)], height_field=f)]:
        height(pack(t), 0.1, 0.2)
    assert len(height.signatures) == 1
