"""Terrain geometry in terrain axes (x, y in the mean plane, z up along its normal; SI units).

The ground is the plane z = 0 shifted by steps, with rocks (hemispheres, boxes) and an optional height field
on it. Steps add: a point on the raised side of several steps is raised by the sum of their heights (a down
step, height < 0, lowers its side). On that base, the surface is the union of the height field (the plane
where there is none) and every rock: the highest of them at each point. Rocks and the height field are thus
measured from the local base, so a rock on the upper side of a step sits on the step. A hemisphere stands on the
ground at FOOT (85 deg): past the radius where its slope reaches that, its foot is the cone tangent to it there.

`pack` turns a Terrain into the arrays the compiled functions take:
steps (k, 5): x, y, cos, sin of the direction, height; hemispheres (k, 3): x, y, radius;
boxes (k, 7): x, y, cos, sin of the yaw, half length, half width, height;
field (1, 6 + nx ny): x0, y0, dx, dy, nx, ny, then z row by row ((0, 6) when there is none).
All are float64 and C-contiguous, so every terrain has the same numba type (one compilation). The plain plane
packs four empty arrays (`is_plane`): `height`, `surface` and `clearance` are inlined into their caller and
test that first, so on the plane they cost a few compares (~1 ns against ~50 ns for a call that reaches the
features, measured).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numba import njit

PLANE, STEP, HEMISPHERE, BOX, HEIGHT_FIELD = -1, 0, 1, 2, 3
FIELD_HEAD = 6
FOOT = 85.0                                      # deg: slope of a hemisphere's foot, where it meets the ground
FOOT_SIN, FOOT_COS = float(np.sin(np.radians(FOOT))), float(np.cos(np.radians(FOOT)))
FACE_GAP = 1e-3                                  # m: a footpad this far above the surface under it is on a face
ACROSS = 1e-9                                    # m: a face's far side is probed this far across it


@dataclass(frozen=True)
class Step:
    """A straight step through (x, y) along direction_deg (from +x towards +y): the ground on the left of the
    directed line is raised by height (m; negative lowers it)."""

    x: float
    y: float
    direction_deg: float
    height: float


@dataclass(frozen=True)
class Hemisphere:
    """A rock: a hemisphere of radius (m) centred at (x, y) on the base, on its conical foot (FOOT)."""

    x: float
    y: float
    radius: float

    def __post_init__(self):
        if not self.radius > 0:
            raise ValueError("a hemisphere's radius must be positive")


@dataclass(frozen=True)
class Box:
    """A rock: a box centred at (x, y), length along yaw_deg (from +x towards +y), width across, height up (m)."""

    x: float
    y: float
    length: float
    width: float
    height: float
    yaw_deg: float = 0.0

    def __post_init__(self):
        if not (self.length > 0 and self.width > 0 and self.height > 0):
            raise ValueError("a box's length, width and height must be positive")


@dataclass(frozen=True, eq=False)
class HeightField:
    """Heights z (m), shape (ny, nx): z[j, i] at (x0 + i dx, y0 + j dy); bilinear between, the plane outside."""

    x0: float
    y0: float
    dx: float
    dy: float
    z: np.ndarray

    def __post_init__(self):
        z = np.array(self.z, dtype=float, order="C")
        if z.ndim != 2 or min(z.shape) < 2 or not np.all(np.isfinite(z)):
            raise ValueError("a height field needs a finite grid of at least 2 x 2 points")
        if not (self.dx > 0 and self.dy > 0):
            raise ValueError("a height field's spacing must be positive")
        z.flags.writeable = False
        object.__setattr__(self, "z", z)

    @classmethod
    def from_file(cls, path: str | Path, dx: float, dy: float, x0: float = 0.0, y0: float = 0.0) -> HeightField:
        """Grid from a .npy array or a .csv of numbers (comma-separated, one row per y, '#' comments)."""
        path = Path(path)
        if path.suffix.lower() == ".npy":
            z = np.load(path, allow_pickle=False)
        elif path.suffix.lower() == ".csv":
            z = np.loadtxt(path, delimiter=",", ndmin=2)
        else:
            raise ValueError(f"{path}: a height field is read from .npy or .csv")
        return cls(x0, y0, dx, dy, z)


@dataclass(frozen=True)
class Terrain:
    """The plane z = 0 with steps, rocks and an optional height field."""

    steps: tuple[Step, ...] = ()
    hemispheres: tuple[Hemisphere, ...] = ()
    boxes: tuple[Box, ...] = ()
    height_field: HeightField | None = None

    def __post_init__(self):
        for name in ("steps", "hemispheres", "boxes"):
            object.__setattr__(self, name, tuple(getattr(self, name)))


def _unit(deg: float) -> tuple[float, float]:
    """(cos, sin) of an angle in degrees, exact on multiples of 90 (an axis-aligned edge holds its own points)."""
    turns, rest = divmod(deg, 90.0)
    if rest == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(turns) % 4]
    return float(np.cos(np.radians(deg))), float(np.sin(np.radians(deg)))


def pack(terrain: Terrain) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(steps, hemispheres, boxes, field) float arrays for the compiled functions (layout in the module doc)."""
    steps = [(s.x, s.y, *_unit(s.direction_deg), s.height) for s in terrain.steps]
    hemispheres = [(h.x, h.y, h.radius) for h in terrain.hemispheres]
    boxes = [(b.x, b.y, *_unit(b.yaw_deg), 0.5 * b.length, 0.5 * b.width, b.height) for b in terrain.boxes]
    f = terrain.height_field
    field = np.zeros((0, FIELD_HEAD)) if f is None else \
        np.concatenate([(f.x0, f.y0, f.dx, f.dy, f.z.shape[1], f.z.shape[0]), f.z.ravel()])[None, :]
    return (np.array(steps, float).reshape(-1, 5), np.array(hemispheres, float).reshape(-1, 3),
            np.array(boxes, float).reshape(-1, 7), np.ascontiguousarray(field, float))


@njit(cache=True, inline="always")
def is_plane(packed) -> bool:
    """Whether the packed terrain is the plain plane z = 0."""
    return (packed[0].shape[0] == 0 and packed[1].shape[0] == 0 and packed[2].shape[0] == 0
            and packed[3].shape[0] == 0)


@njit(cache=True)
def _field(row, x: float, y: float):
    """(inside, z, dz/dx, dz/dy) of the packed height field row at (x, y)."""
    nx, ny = int(row[4]), int(row[5])
    u, v = (x - row[0]) / row[2], (y - row[1]) / row[3]             # grid coordinates
    if not (0.0 <= u <= nx - 1 and 0.0 <= v <= ny - 1):
        return False, 0.0, 0.0, 0.0
    i, j = min(int(u), nx - 2), min(int(v), ny - 2)                 # the cell, the last one for the far edges
    fu, fv = u - i, v - j
    k = FIELD_HEAD + j * nx + i
    z00, z10, z01, z11 = row[k], row[k + 1], row[k + nx], row[k + nx + 1]
    z = z00 * (1 - fu) * (1 - fv) + z10 * fu * (1 - fv) + z01 * (1 - fu) * fv + z11 * fu * fv   # bilinear
    zx = ((z10 - z00) * (1 - fv) + (z11 - z01) * fv) / row[2]       # d/dx of the bilinear form
    zy = ((z01 - z00) * (1 - fu) + (z11 - z10) * fu) / row[3]       # d/dy of the bilinear form
    return True, z, zx, zy


@njit(cache=True)
def _relief(packed, x: float, y: float):
    """(z, n0, n1, n2, kind, index) of the continuous relief on the base at (x, y): the highest of the height field
    (the plane where there is none) and the hemispheres, its unit normal and which it is (PLANE, -1 where neither)."""
    _, hemispheres, _, field = packed
    kind, index = PLANE, -1
    z, n0, n1, n2 = 0.0, 0.0, 0.0, 1.0
    if field.shape[0] > 0:
        inside, zf, zx, zy = _field(field[0], x, y)
        if inside:
            m = 1.0 / np.sqrt(1.0 + zx * zx + zy * zy)
            z, n0, n1, n2, kind, index = zf, -zx * m, -zy * m, m, HEIGHT_FIELD, 0   # normal of z = f(x, y)
    for i in range(hemispheres.shape[0]):
        dx, dy, r = x - hemispheres[i, 0], y - hemispheres[i, 1], hemispheres[i, 2]
        d2 = dx * dx + dy * dy
        if d2 < (r / FOOT_SIN) ** 2:
            if d2 <= (r * FOOT_SIN) ** 2:
                zh = np.sqrt(r * r - d2)                            # sphere z = sqrt(r^2 - d^2), radial normal
                m0, m1, m2 = dx / r, dy / r, zh / r
            else:                                                   # its foot: the cone tangent to it at FOOT
                d = np.sqrt(d2)
                zh = (r / FOOT_SIN - d) * FOOT_SIN / FOOT_COS
                m0, m1, m2 = FOOT_SIN * dx / d, FOOT_SIN * dy / d, FOOT_COS
            if zh > z:
                z, n0, n1, n2, kind, index = zh, m0, m1, m2, HEMISPHERE, i
    return z, n0, n1, n2, kind, index


@njit(cache=True)
def _top(packed, x: float, y: float):
    """(z, n0, n1, n2, kind, index) of the surface at (x, y): height, unit normal, the feature on top."""
    steps, _, boxes, _ = packed
    base, kind, index, near = 0.0, PLANE, -1, np.inf
    for i in range(steps.shape[0]):
        s = steps[i, 2] * (y - steps[i, 1]) - steps[i, 3] * (x - steps[i, 0])   # distance left of the edge
        h = steps[i, 4]
        if s > 0.0 or (s == 0.0 and h > 0.0):                       # the shifted side; the edge goes with the upper
            base += h
            if s < near:                                            # the nearest edge names the step
                kind, index, near = STEP, i, s
    z, n0, n1, n2, k, j = _relief(packed, x, y)
    if k != PLANE:
        kind, index = k, j
    for i in range(boxes.shape[0]):
        dx, dy = x - boxes[i, 0], y - boxes[i, 1]
        a, b = boxes[i, 2] * dx + boxes[i, 3] * dy, boxes[i, 2] * dy - boxes[i, 3] * dx   # along, across the yaw
        if abs(a) <= boxes[i, 4] and abs(b) <= boxes[i, 5] and boxes[i, 6] > z:   # the top, edges included
            z, n0, n1, n2, kind, index = boxes[i, 6], 0.0, 0.0, 1.0, BOX, i
    return base + z, n0, n1, n2, kind, index


@njit(cache=True, inline="always")
def height(packed, x: float, y: float) -> float:
    """z of the surface at (x, y)."""
    return 0.0 if is_plane(packed) else _top(packed, x, y)[0]


@njit(cache=True, inline="always")
def surface(packed, x: float, y: float):
    """(z, n0, n1, n2): height and unit outward normal of the feature on top at (x, y) ((0, 0, 1) on flat parts)."""
    if is_plane(packed):
        return 0.0, 0.0, 0.0, 1.0
    z, n0, n1, n2, _, _ = _top(packed, x, y)
    return z, n0, n1, n2


@njit(cache=True, inline="always")
def relief(packed, x: float, y: float):
    """(c, n0, n1, n2): height above the base of the continuous relief at (x, y), the highest of the height field and
    the hemispheres (0 where neither), and its unit outward normal ((0, 0, 1) on flat parts). A footpad sliding on
    the ground follows it; steps and boxes, whose faces are vertical, it does not."""
    if packed[1].shape[0] == 0 and packed[3].shape[0] == 0:
        return 0.0, 0.0, 0.0, 1.0
    c, n0, n1, n2, _, _ = _relief(packed, x, y)
    return c, n0, n1, n2


@njit(cache=True, inline="always")
def clearance(packed, p0: float, p1: float, p2: float) -> float:
    """Vertical clearance p2 - height(p0, p1) of the point p."""
    return p2 - height(packed, p0, p1)


@njit(cache=True)
def face_normal(packed, x: float, y: float, z: float):
    """(found, n0, n1): the outward horizontal unit normal of the vertical face nearest (x, y) whose far side rises
    above z, a step's riser or a box's side (at a box's corner the direction from it), the face a footpad at
    (x, y, z) held on it bears on."""
    steps, _, boxes, _ = packed
    near, n0, n1 = np.inf, 0.0, 0.0
    for i in range(steps.shape[0]):
        c, s = steps[i, 2], steps[i, 3]
        d = c * (y - steps[i, 1]) - s * (x - steps[i, 0])            # distance left of the edge
        m0, m1 = (-s, c) if d >= 0.0 else (s, -c)
        a = abs(d) + ACROSS
        if abs(d) < near and height(packed, x - a * m0, y - a * m1) > z:
            near, n0, n1 = abs(d), m0, m1
    for i in range(boxes.shape[0]):
        c, s = boxes[i, 2], boxes[i, 3]
        dx, dy = x - boxes[i, 0], y - boxes[i, 1]
        a, b = c * dx + s * dy, c * dy - s * dx                         # along, across the yaw
        ea, eb = a - min(max(a, -boxes[i, 4]), boxes[i, 4]), b - min(max(b, -boxes[i, 5]), boxes[i, 5])
        d = np.sqrt(ea * ea + eb * eb)                                  # from the box's footprint
        if not 0.0 < d < near:
            continue
        m0, m1 = (c * ea - s * eb) / d, (s * ea + c * eb) / d
        if height(packed, x - (d + ACROSS) * m0, y - (d + ACROSS) * m1) > z:
            near, n0, n1 = d, m0, m1
    return near < np.inf, n0, n1


@njit(cache=True)
def bearing_normal(packed, x: float, y: float, z: float):
    """(n0, n1, n2): the unit outward normal of the terrain a footpad at (x, y, z) bears on: on the surface (within
    FACE_GAP above it, or below it on soil) the relief's; higher, held on a vertical face beside it (a step's riser, a
    box's side), that face's."""
    if not is_plane(packed) and z - height(packed, x, y) > FACE_GAP:
        found, n0, n1 = face_normal(packed, x, y, z)
        if found:
            return n0, n1, 0.0
    _, n0, n1, n2 = relief(packed, x, y)
    return n0, n1, n2


@njit(cache=True)
def foot_distance(packed, x: float, y: float) -> float:
    """Horizontal distance from (x, y) to where the nearest hemisphere meets the ground, negative within one (at most
    1 m: an event function's value away from rocks)."""
    hemispheres = packed[1]
    d = 1.0
    for i in range(hemispheres.shape[0]):
        d = min(d, np.hypot(x - hemispheres[i, 0], y - hemispheres[i, 1]) - hemispheres[i, 2] / FOOT_SIN)
    return d


@njit(cache=True)
def features_at(packed, x: float, y: float):
    """(kind, index) of the feature on top at (x, y): a rock or the height field where one is, else the step whose
    shifted side holds the point (the nearest edge), else (PLANE, -1)."""
    _, _, _, _, kind, index = _top(packed, x, y)
    return kind, index


@njit(cache=True)
def features_along(packed, xy):
    """features_at for every row (x, y) of xy: (kinds, indices) arrays."""
    kinds, indices = np.full(xy.shape[0], PLANE), np.full(xy.shape[0], -1)
    if not is_plane(packed):
        for k in range(xy.shape[0]):
            kinds[k], indices[k] = features_at(packed, xy[k, 0], xy[k, 1])
    return kinds, indices


def _uniform(rng: np.random.Generator, bounds: tuple[float, float]) -> float:
    return float(rng.uniform(bounds[0], bounds[1]))


def random_feature(rng: np.random.Generator, span: float, *, step_height: tuple[float, float] | None = None,
                   radius: tuple[float, float] | None = None, box_size: tuple[float, float] | None = None,
                   box_height: tuple[float, float] | None = None) -> Terrain:
    """One step, hemisphere or box (equally likely among the kinds whose size ranges are given) at a point drawn
    uniformly in the disc of radius span about the origin, direction or yaw uniform; a box's length and width
    are drawn from box_size, its height from box_height. All draws come from rng."""
    if (box_size is None) != (box_height is None):
        raise ValueError("a box needs both box_size and box_height")
    kinds = [k for k, given in ((STEP, step_height), (HEMISPHERE, radius), (BOX, box_size)) if given is not None]
    if not kinds or not span > 0:
        raise ValueError("give a positive span and at least one size range")
    kind = kinds[int(rng.integers(len(kinds)))]
    rho, theta = span * np.sqrt(rng.uniform()), 2.0 * np.pi * rng.uniform()   # uniform in the disc
    x, y = float(rho * np.cos(theta)), float(rho * np.sin(theta))
    if kind == STEP:
        return Terrain(steps=(Step(x, y, 360.0 * float(rng.uniform()), _uniform(rng, step_height)),))
    if kind == HEMISPHERE:
        return Terrain(hemispheres=(Hemisphere(x, y, _uniform(rng, radius)),))
    return Terrain(boxes=(Box(x, y, _uniform(rng, box_size), _uniform(rng, box_size), _uniform(rng, box_height),
                              360.0 * float(rng.uniform())),))
