"""The formula every stress- and weight-sheet line prints is the formula the code evaluated: for every check kind
and weight method (enumerated from their registries), seeded random inputs over each branch, each Step's displayed
formula evaluated with the values it records must give the value the code computed (rel 1e-12: the same
arithmetic in another order, a few ulps, never a wrong coefficient or term).

The display notation (alightsize.common.trace.Step) read here: {name} an input; juxtaposition multiplies, left to
right like * and /; a number written against a symbol (2π, 3m) is one factor, so "{F} / 2π" is F / (2π); ² ³ ⁴
powers, x^(y) a power of any exponent; √(x), √2; |x|; [ ] as ( ); ln, exp, min, max; π; "expr, F = expr" defines F
for expr (a clause may name the line's own symbol: "σt = σr / {m}"). Evaluated by a restricted walk of Python's ast:
no other names or calls."""

from __future__ import annotations

import ast
import math
import random
import re

import pytest

from alightsize.checks.kinds import KINDS, read_check
from alightsize.common.config import Node
from alightsize.common.trace import Step
from alightsize.model.materials import Material
from alightsize.model.sections import Section
from alightsize.weights.methods import METHODS, read_weight

REL = 1e-12          # same formula, operations reordered: within a few ulps of double precision

# ---------------------------------------------------------------- the display-formula evaluator

_TOKEN = re.compile(r"\s*(?:(?P<brace>\{[^{}]+\})|(?P<num>\d+\.?\d*|\.\d+)|(?P<sup>[²³⁴])"
                    r"|(?P<name>[A-Za-zα-ωΑ-Ω_][A-Za-z0-9α-ωΑ-Ω_]*)|(?P<op>[-+*/(),=|√^\[\]]))")
_SUP = {"²": "2", "³": "3", "⁴": "4"}
_BINARY = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b,
           ast.Div: lambda a, b: a / b, ast.Pow: lambda a, b: a ** b}
_FUNCS = {"ln": math.log, "exp": math.exp, "min": min, "max": max, "sqrt": math.sqrt, "abs": abs}


def _tokens(text: str) -> list[tuple[str, str, bool]]:
    """(kind, text, glued to the previous token) of a display formula; ValueError on any other character."""
    out, pos = [], 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            if text[pos:].strip() == "":
                break
            raise ValueError(f"not a formula at {text[pos:]!r}")
        kind = m.lastgroup
        out.append((kind, m.group(kind), m.start(kind) == pos))
        pos = m.end()
    return out


def _python(text: str, names: dict[str, str]) -> str:
    """The display formula as Python source; `names` maps each {input} to a safe identifier."""
    toks, out, prev = _tokens(text), [], "start"      # prev: "value" (ends an operand), "func", or "op"/"start"
    i = 0
    while i < len(toks):
        kind, tok, _ = toks[i]
        glued_next = i + 1 < len(toks) and toks[i + 1][2]
        starts_value = kind in ("brace", "num", "name") or tok in ("(", "[", "√") or (tok == "|" and prev != "value")
        if starts_value and prev == "value":
            out.append("*")
        if kind == "brace":
            out.append(names[tok[1:-1]])
            prev = "value"
        elif kind == "num":
            nxt = toks[i + 1] if i + 1 < len(toks) else None
            after = toks[i + 2] if i + 2 < len(toks) else None
            if (nxt and glued_next and nxt[0] in ("name", "brace") and nxt[1] not in _FUNCS
                    and not (after and after[2] and after[0] == "sup")):
                second = names[nxt[1][1:-1]] if nxt[0] == "brace" else ("pi" if nxt[1] == "π" else nxt[1])
                out.append(f"({tok}*{second})")        # 2π: one factor
                i += 1
            else:
                out.append(tok)
            prev = "value"
        elif kind == "sup":
            if prev != "value":
                raise ValueError(f"a power of nothing in {text!r}")
            out.append("**" + _SUP[tok])
        elif kind == "name":
            if tok in ("ln", "exp", "min", "max"):
                out.append(tok)
                prev = "func"
            else:
                out.append("pi" if tok == "π" else tok)
                prev = "value"
        elif tok == "√":
            nxt = toks[i + 1] if i + 1 < len(toks) else None
            if nxt and nxt[0] in ("num", "brace"):     # √2: the root of one operand
                out.append(f"sqrt({names[nxt[1][1:-1]] if nxt[0] == 'brace' else nxt[1]})")
                i += 1
                prev = "value"
            else:
                out.append("sqrt")
                prev = "func"
        elif tok == "|":
            out.append("abs(" if prev != "value" else ")")
            prev = "op" if out[-1] == "abs(" else "value"
        elif tok in "([":
            out.append("(")
            prev = "op"
        elif tok in ")]":
            out.append(")")
            prev = "value"
        elif tok == "^":
            out.append("**")
            prev = "op"
        else:
            out.append(tok)
            prev = "op"
        i += 1
    return " ".join(out)


def _walk(node: ast.AST, env: dict[str, float]) -> float:
    if isinstance(node, ast.Expression):
        return _walk(node.body, env)
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return node.value
    if isinstance(node, ast.Name):
        if node.id == "pi":
            return math.pi
        if node.id not in env:
            raise ValueError(f"{node.id} is neither an input of the line nor defined in it")
        return env[node.id]
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        v = _walk(node.operand, env)
        return -v if isinstance(node.op, ast.USub) else v
    if isinstance(node, ast.BinOp) and type(node.op) in (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow):
        a, b = _walk(node.left, env), _walk(node.right, env)
        return _BINARY[type(node.op)](a, b)
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _FUNCS
            and not node.keywords):
        return _FUNCS[node.func.id](*(_walk(a, env) for a in node.args))
    raise ValueError(f"not allowed in a display formula: {ast.dump(node)}")


def _clauses(text: str) -> list[str]:
    """Split at the commas outside brackets and bars: the expression, then its `NAME = expr` clauses."""
    parts, depth, bars, start = [], 0, 0, 0
    for j, ch in enumerate(text):
        depth += ch in "([{" and 1 or (ch in ")]}" and -1 or 0)
        bars ^= ch == "|"
        if ch == "," and depth == 0 and not bars:
            parts.append(text[start:j])
            start = j + 1
    return [*parts, text[start:]]


def evaluate(step: Step) -> float:
    """The value of a Step's displayed formula with the inputs it records."""
    names = {n: f"_v{j}" for j, (n, _, _) in enumerate(step.inputs)}
    env = {names[n]: v for n, v, _ in step.inputs}
    main, *where = _clauses(step.formula)
    for clause in where:
        lhs, _, rhs = clause.partition("=")
        name = lhs.strip()
        if not rhs or not name.isidentifier():
            raise ValueError(f"clause {clause!r} of {step.formula!r} is not NAME = expression")
        own = {**env, step.symbol: step.value} if step.symbol.isidentifier() else env
        env[name] = _walk(ast.parse(_python(rhs, names), mode="eval"), own)
    return _walk(ast.parse(_python(main, names), mode="eval"), env)


def test_evaluator_reads_the_notation():
    # Hand-worked: 2π binds as one factor; juxtaposition is left-to-right multiplication; bars and clauses.
    s = Step("", "x", "({a} / 2π)² {b} + |{c}| {a}, F = 1", (("a", 3.0, ""), ("b", 2.0, ""), ("c", -4.0, "")), 0, "")
    assert evaluate(s) == pytest.approx((3 / (2 * math.pi)) ** 2 * 2 + 4 * 3, rel=1e-15)
    s = Step("", "x", "0.5 ({a} {b})^(1/3) {c}", (("a", 3.0, ""), ("b", 2.0, ""), ("c", -4.0, "")), 0, "")
    assert evaluate(s) == pytest.approx(0.5 * 6 ** (1 / 3) * -4, rel=1e-15)
    s = Step("", "x", "{ρ} π/4 ({d}² - 6 {h}²) {t}, k = x", (("ρ", 2.0, ""), ("d", 3.0, ""), ("h", 0.5, ""),
                                                             ("t", 0.1, "")), 5.0, "")
    assert evaluate(s) == pytest.approx(2 * math.pi / 4 * (9 - 1.5) * 0.1, rel=1e-15)
    for bad in ("__import__('os')", "{a}.real", "q {a}", "6 M/t² of {a}"):
        with pytest.raises((ValueError, SyntaxError)):
            evaluate(Step("", "x", bad, (("a", 1.0, ""),), 1.0, ""))


# ---------------------------------------------------------------- random inputs over every branch

def _u(rng: random.Random, lo: float, hi: float) -> float:
    return rng.uniform(lo, hi)


def _material(rng: random.Random) -> Material:
    return Material("m", "test metal", density=_u(rng, 2000, 8000), yield_strength=_u(rng, 2e8, 6e8),
                    elastic_modulus=_u(rng, 6e10, 2.1e11), poisson_m=_u(rng, 2.8, 3.6))


def _tube(rng, r_over_t: float | None = None) -> Section:
    od = _u(rng, 0.02, 0.1)
    rt = r_over_t if r_over_t is not None else _u(rng, 12, 60)
    wall = od / (2 * rt + 1)                        # r = (od - t)/2 = rt t
    return Section("tube", {"outside_diameter": od, "wall": wall})


def _rod(rng) -> Section:
    return Section("rod", {"diameter": _u(rng, 0.005, 0.03)})


def _plate(rng, inner: bool = False) -> Section:
    d = _u(rng, 0.05, 0.2)
    dims = {"diameter": d, "thickness": d * _u(rng, 0.02, 0.2)}
    if inner:
        dims["inner_diameter"] = d * _u(rng, 0.15, 0.7)
    return Section("plate", dims)


_CORE = Material("core", "test honeycomb", density=50.0, elastic_modulus=5e8, compressive_strength=2e6,
                 shear_strength=9e5, shear_modulus=1.5e8, cell_size=3.2e-3)


def _sandwich(rng) -> Section:
    d = _u(rng, 0.3, 1.0)
    return Section("sandwich", {"diameter": d, "face": _u(rng, 2e-4, 2e-3), "core_depth": d * _u(rng, 0.02, 0.15)},
                   core=_CORE)


def _force(rng, signed: bool = True) -> str:
    return f"{_u(rng, 1e3, 1e5) * (rng.choice((-1, 1)) if signed else 1)!r} N"


def _moment(rng) -> dict:
    if rng.random() < 0.5:
        return {"moment": f"{_u(rng, 10, 2000) * rng.choice((-1, 1))!r} N*m"}
    return {"moment_force": _force(rng), "moment_arm": f"{_u(rng, 0.01, 0.3)!r} m"}


def _plate_load(rng, s: Section, theory: str, equivalent: bool) -> dict:
    a, t = s.dims["diameter"] / 2, s.dims["thickness"]
    small = equivalent and rng.random() < 0.7
    r0 = t * _u(rng, 0.1, 0.45) if small else a * _u(rng, 0.05, 0.3)
    return {"load": _force(rng, False), "load_radius": f"{r0!r} m", "theory": theory, "equivalent_radius": equivalent}


def _cases(kind: str, rng: random.Random) -> list[tuple[dict, Section]]:
    """Raw check tables (as a config gives them, SI units) with the section each is evaluated on."""
    theories = ("app_iv", "tresca", "von_mises")
    if kind in ("compression", "tension"):
        return [({"load": _force(rng)}, rng.choice((_tube(rng), _rod(rng))))]
    if kind == "bending":
        return [(_moment(rng), rng.choice((_tube(rng), _rod(rng))))]
    if kind == "combined":
        return [({"load": _force(rng), **_moment(rng)}, _tube(rng))]
    if kind == "column_buckling":               # short (Johnson) and long (Euler) columns, both formulas
        s = _tube(rng)
        k = math.sqrt(s.inertia() / s.area())
        return [({"load": _force(rng), "length": f"{k * slender!r} m", "formula": f}, s)
                for f in ("euler", "johnson_euler") for slender in (_u(rng, 5, 40), _u(rng, 150, 400))]
    if kind == "local_buckling":                 # thin and thick walls, both formulas, with and without moment,
        out = []                                 # the wall from the check or the section
        for f in ("app_iv", "sp8007"):
            for rt in (_u(rng, 12, 40), _u(rng, 100, 400), _u(rng, 2, 9)):
                extra = _moment(rng) if rng.random() < 0.5 else {}
                s = _tube(rng, rt)
                own = {"wall": f"{s.wall!r} m"} if rng.random() < 0.5 else {}
                if own:
                    s = s.with_dim("wall", s.wall * 1.3)
                out.append(({"load": _force(rng), "formula": f, **own, **extra}, s))
        return out
    if kind == "bearing":
        return [({"loads": [_force(rng) for _ in range(rng.randint(1, 3))], "combine": c,
                  "bearing_length": f"{_u(rng, 0.003, 0.03)!r} m", **({"diameter": "0.011 m"} if c == "sum" else {}),
                  **({"material": "lug"} if lug else {})}, _rod(rng))
                for c in ("resultant", "sum") for lug in (False, True)]
    if kind == "pin_shear":
        return [({"loads": [_force(rng) for _ in range(rng.randint(1, 3))], "allowable_load": _force(rng, False)},
                 _rod(rng))]
    if kind == "pin_double_shear":
        return [({"loads": [_force(rng) for _ in range(rng.randint(1, 3))], "planes": rng.randint(1, 4),
                  **({"diameter": "0.012 m"} if rng.random() < 0.5 else {})}, _rod(rng))]
    if kind == "ring_bending":
        s = _tube(rng)
        return [({"load": _force(rng), "span": f"{s.c() * _u(rng, 4, 40)!r} m"}, s)]
    if kind == "cone_tension":
        return [({"load": _force(rng), "thickness": f"{_u(rng, 0.001, 0.01)!r} m"}, _rod(rng))]
    if kind in ("plate_fixed_center_load", "plate_supported_center_load"):
        out = []
        for theory in theories:
            for eq in (False, True):
                s = _plate(rng)
                out.append((_plate_load(rng, s, theory, eq), s))
        s = _plate(rng)                        # outside the range: a load circle wider than the plate
        out.append(({"load": _force(rng, False), "load_radius": f"{s.dims['diameter']!r} m"}, s))
        return out
    if kind.startswith("plate_") and kind.endswith("_moment_and_load"):
        formulas = [("thin_plate", False)] + ([("app_iv", False), ("app_iv", True)] if "fixed" in kind else [])
        out = []
        for f, squared in formulas:
            for theory in theories:
                s = _plate(rng)
                t = _plate_load(rng, s, theory, rng.random() < 0.5)
                out.append(({**t, **_moment(rng), "formula": f, **({"pi_squared": True} if squared else {})}, s))
        return out
    if kind.startswith("plate_annular_"):
        return [({"pressure": f"{_u(rng, 1e5, 5e6)!r} Pa"}, _plate(rng, inner=True)) for _ in range(2)]
    if kind == "plate_supported_eccentric_and_distributed":
        out = []
        for f in ("app_iv", "thin_plate"):
            for theory in theories:
                s = _plate(rng)
                a = s.dims["diameter"] / 2
                p, r0 = a * _u(rng, 0.05, 0.4), a * _u(rng, 0.05, 0.3)
                at = {"radius_tangential": f"{a * 1.02!r} m"} if f == "app_iv" and rng.random() < 0.5 else {}
                out.append(({"load": _force(rng, False), "distributed_load": _force(rng, False),
                             "load_offset": f"{p!r} m", "load_radius": f"{r0!r} m", "formula": f, "theory": theory,
                             "equivalent_radius": rng.random() < 0.5, **at}, s))
        return out
    if kind.startswith("sandwich_"):             # every theory (face stress); inside and outside the range
        out = []
        for theory in theories:
            s = _sandwich(rng)
            raw = {"load": _force(rng, False), "load_radius": f"{s.dims['diameter'] * _u(rng, 0.05, 0.4)!r} m"}
            out.append(({**raw, **({"theory": theory} if kind == "sandwich_face_stress" else {})}, s))
        s = _sandwich(rng)
        out.append(({"load": _force(rng, False), "load_radius": f"{s.dims['diameter']!r} m"}, s))
        return out
    raise KeyError(kind)


# Lines whose "formula" names a numerical thin-plate solution rather than a closed form (it cannot be
# evaluated from the line): tests/validation/test_plates.py checks those solutions against published tables.
DESCRIBED = {("plate_annular_", "stress at the"), ("plate_supported_eccentric_and_distributed",
                                                   "stress due to the eccentric load (thin plate")}


def _described(kind: str, step: Step) -> bool:
    return any(kind.startswith(k) and s in step.label for k, s in DESCRIBED) and " of " in step.formula


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_check_formulas_are_what_the_code_computes(kind):
    rng = random.Random(f"display-{kind}")
    lines = 0
    for _ in range(4):
        for raw, section in _cases(kind, rng):
            check = read_check(Node("test.toml", "items.x.checks[0]", {"kind": kind, **raw}))
            mat = _material(rng)
            if check.params.get("material") == "lug":
                check.params["material"] = Material("lug", "lug metal", 2800.0, yield_strength=_u(rng, 1e8, 7e8))
            for step in check.evaluate(section, mat).steps:
                if _described(kind, step):
                    continue
                value = evaluate(step)
                assert math.isclose(value, step.value, rel_tol=REL), (kind, step.label, step.formula, value,
                                                                       step.value)
                lines += 1
    assert lines, f"{kind}: no line evaluated"


def test_every_check_kind_has_inputs_here():
    rng = random.Random(0)
    for kind in KINDS:
        assert _cases(kind, rng), kind           # a new kind without cases raises KeyError here


_MATERIALS = {"al": Material("al", "aluminium", 2800.0), "steel": Material("steel", "steel", 7850.0)}


def _weights(method: str, rng: random.Random) -> list[tuple[dict, Section | None]]:
    extras = [{}, {"allowance": _u(rng, 0.01, 0.2)}, {"extra": f"{_u(rng, 0.01, 1)!r} kg"}]
    length = {"length": f"{_u(rng, 0.1, 1.5)!r} m"}
    if method == "fixed":
        return [({"weight": f"{_u(rng, 0.1, 20)!r} kg"}, None)]
    if method == "scaled":
        return [({"k": _u(rng, 0.5, 2), "model_weight": f"{_u(rng, 0.1, 5)!r} kg", "length_ratio": _u(rng, 0.5, 3),
                  **({"area_ratio": _u(rng, 0.5, 4)} if by_ratio else {"model_area": f"{_u(rng, 1e-5, 1e-3)!r} m^2"}),
                  **({"density_ratio": _u(rng, 0.3, 3)} if dens else {"model_material": "steel"})}, _tube(rng))
                for by_ratio in (True, False) for dens in (True, False)]
    if method == "tube":
        return [({**length, "density": f"{_u(rng, 2000, 8000)!r} kg/m^3", **e}, _tube(rng)) for e in extras] + [
            ({**length, "material": "al", "diameter": "0.05 m", "wall": "0.002 m"}, None)]
    if method == "disc":
        return [({"material": "al", "holes": holes, **({"hole_diameter": "0.004 m"} if holes else {}),
                  **({"inner_diameter": f"{_u(rng, 0.005, 0.02)!r} m"} if inner else {}), **e},
                 _plate(rng)) for holes in (0, 6) for inner in (False, True) for e in extras]
    if method == "sandwich":
        return [(e, _sandwich(rng)) for e in extras] + [({"material": "steel"}, _sandwich(rng))]
    if method == "prism":
        return [({**length, "material": "steel", **a, **e}, None) for e in extras
                for a in ({"area": "2e-4 m^2"}, {"diameter": "0.01 m"}, {"width": "0.02 m", "height": "0.01 m"})] + [
            ({**length, "material": "al"}, _rod(rng))]
    raise KeyError(method)


@pytest.mark.parametrize("method", METHODS)
def test_weight_formulas_are_what_the_code_computes(method):
    rng = random.Random(f"display-{method}")
    for _ in range(4):
        for raw, section in _weights(method, rng):
            spec = read_weight(Node("test.toml", "items.x.weight", {"method": method, **raw}), _MATERIALS)
            weight, steps = spec.evaluate(section, Material("al", "aluminium", 2800.0), _u(rng, 0.1, 1))
            for step in steps:
                value = evaluate(step)
                assert math.isclose(value, step.value, rel_tol=REL), (method, step.label, step.formula, value,
                                                                       step.value)
            assert math.isclose(sum(s.value for s in steps if s.symbol in ("W", "ΔW")) if len(steps) > 1
                                else steps[0].value, weight, rel_tol=REL)
