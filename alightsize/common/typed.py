"""Typed input tables (pydantic v2): each key's type, quantities parsed to SI through `common.units` (dimension
and magnitude range checked, nothing evaluated), unknown keys refused by the name written (with a suggestion),
and a validation error turned into the InputError contract: file, key path as written, expected, found."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

from pydantic import BaseModel, ConfigDict, Discriminator, PlainValidator, Tag, ValidationError, model_validator
from pydantic_core import PydanticCustomError

from alightsize.common import units
from alightsize.common.config import _close, _describe, _unknown, key_name
from alightsize.common.errors import InputError

_ERROR = "alightsize"          # the type of the errors raised here (their context carries expected and found)
Sign = Literal["positive", "any", "nonnegative"]


def refuse(expected: str, found: str | None = None, key: str | None = None) -> PydanticCustomError:
    """A validation error at the value being validated (or at `key` below it: "name", "[2]", "legs.axial")."""
    return PydanticCustomError(_ERROR, "{expected}", {"expected": expected, "found": found, "key": key})


class Table(BaseModel):
    """A TOML table: its keys are its fields; any other key is refused (a typo must never pass silently)."""

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, arbitrary_types_allowed=True)

    @model_validator(mode="before")
    @classmethod
    def _known_keys(cls, data: Any) -> Any:
        if not isinstance(data, dict):
            return data
        known = {f.alias or k: f for k, f in cls.model_fields.items()}      # keys as written ("from": alias)
        unknown = sorted(set(data) - set(known))
        if unknown:
            key = unknown[0]
            required = [k for k, f in known.items() if f.is_required() and k not in data]
            meant = _close(key, required)
            if meant is not None:          # named as written, so the user finds it
                raise refuse(f"the required key {meant!r}", f"{key!r} (did you mean {meant!r}?)", key)
            raise refuse("one of the known keys (" + ", ".join(sorted(known)) + ")", _unknown(key, known), key)
        return data


def _sign_check(si: float, dim: str, sign: Sign) -> None:
    if sign == "positive" and si <= 0:
        raise refuse(f"a positive {dim}")
    if sign == "nonnegative" and si < 0:
        raise refuse(f"a {dim} of 0 or more")


def quantity(value: Any, dim: str, sign: Sign) -> float:
    try:
        si = units.parse(value, dim)
    except ValueError as exc:
        raise refuse(str(exc)) from None
    _sign_check(si, dim, sign)
    return float(si)


def Quantity(dim: str, sign: Sign = "positive") -> PlainValidator:  # noqa: N802 - a type's validator
    """A quantity with units ("3750 lbf"), validated to an SI float (angles in radians):
    `Annotated[float, Quantity("length")]`."""
    return PlainValidator(lambda v: quantity(v, dim, sign))


def _number(value: Any, sign: Sign) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise refuse("a number")
    low, high, _ = units.RANGES["dimensionless"]
    if not (value == 0 or low <= abs(value) <= high) or (sign == "positive" and value <= 0) or \
            (sign == "nonnegative" and value < 0):                # NaN fails too
        what = {"positive": "a positive number", "any": "a number", "nonnegative": "a number of 0 or more"}[sign]
        raise refuse(what + f" of magnitude {low:g} to {high:g}" + ("" if sign == "positive" else " (or 0)"))
    return float(value)


def _at_most(value: float, most: float | None) -> float:
    if most is not None and value > most:
        raise refuse(f"a number of at most {most:g}")
    return value


def Number(sign: Sign = "positive", most: float | None = None) -> PlainValidator:  # noqa: N802 - a type's validator
    """A plain number (no unit) of a magnitude units.RANGES["dimensionless"] allows, at most `most` if given:
    `Annotated[float, Number()]`."""
    return PlainValidator(lambda v: _at_most(_number(v, sign), most))


def _integer(value: Any, minimum: int, maximum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not minimum <= value <= maximum:
        raise refuse(f"an integer from {minimum:,} to {maximum:,}")
    return value


def Integer(minimum: int = 1, maximum: int = 1_000_000) -> PlainValidator:  # noqa: N802 - a type's validator
    """An integer from `minimum` to `maximum` (every count an input gives has a finite range):
    `Annotated[int, Integer(0, 12)]`."""
    return PlainValidator(lambda v: _integer(v, minimum, maximum))


_COUNT = {2: "two", 3: "three"}


def _quantities(value: Any, dim: str, sign: Sign, count: int | None, minimum: int) -> tuple[float, ...]:
    if not isinstance(value, list) or (count is not None and len(value) != count) or len(value) < minimum:
        what = f"an array of {_COUNT.get(count, count)}" if count else "an array of"
        more = f" ({minimum} or more)" if minimum else ""
        raise refuse(f"{what} {dim} quantities{more}", repr(value))
    out = []
    for i, v in enumerate(value):
        try:
            out.append(quantity(v, dim, sign))
        except PydanticCustomError as exc:
            raise refuse(exc.context["expected"], _describe(v), f"[{i}]") from None
    return tuple(out)


def Quantities(dim: str, sign: Sign = "any", count: int | None = None,  # noqa: N802 - a type's validator
               minimum: int = 0) -> PlainValidator:
    """An array of quantities, `count` of them (a vector) or at least `minimum`:
    `Annotated[tuple[float, ...], Quantities("length", count=3)]`."""
    return PlainValidator(lambda v: _quantities(v, dim, sign, count, minimum))


def Tagged(key: str, default: str | None, *members: type[Table]):  # noqa: N802 - a type
    """One of `members` (each with a Literal field `key`), chosen by the table's `key` (`default` when absent)."""
    def tag(value: Any) -> Any:
        return value.get(key, default) if isinstance(value, dict) else default
    tag.__name__ = key                  # pydantic names the discriminator by it in errors
    choices = tuple(Annotated[m, Tag(m.model_fields[key].annotation.__args__[0])] for m in members)
    return Annotated[Union[choices], Discriminator(tag)]


def _key_path(loc: tuple, data: Any, missing: bool) -> list[str]:
    """The key path of `loc` as the user wrote it: the parts of pydantic's location that are keys and indexes of
    the data (union tags and validator names are not), the last one too when it is missing."""
    parts: list[str] = []
    node = data
    for k, p in enumerate(loc):
        if isinstance(node, dict) and isinstance(p, str) and p in node:
            parts.append(key_name(p))
            node = node[p]
        elif isinstance(node, list) and isinstance(p, int) and 0 <= p < len(node) and parts:
            parts[-1] += f"[{p}]"
            node = node[p]
        elif missing and k == len(loc) - 1 and isinstance(p, str):
            parts.append(p)
    return parts


_EXPECTED = {"string_type": "a string", "bool_type": "true or false", "model_type": "a table",
             "dict_type": "a table", "list_type": "an array", "tuple_type": "an array", "int_type": "an integer",
             "float_type": "a number"}


def input_error(exc: ValidationError, data: Any, file: str, path: str = "") -> InputError:
    """The InputError of a validation's first error: file, key path as written (below `path`), expected, found."""
    err = exc.errors(include_url=False)[0]
    kind, ctx = err["type"], err.get("ctx") or {}
    parts = _key_path(err["loc"], data, kind == "missing")
    found = _describe(err["input"])
    if kind == _ERROR:
        expected, found = ctx["expected"], ctx["found"] or found
        sub = ctx["key"]
        if sub is not None:
            if sub.startswith("[") and parts:
                parts[-1] += sub
            else:
                parts.append(key_name(sub))
    elif kind == "missing":
        expected, found = "this key to be present", "nothing"
    elif kind == "literal_error":
        expected, found = "one of " + ctx["expected"].replace(" or ", ", "), repr(err["input"])
    elif kind == "union_tag_invalid":
        tag = ctx["discriminator"].strip("'").removesuffix("()")
        parts.append(tag)
        value = err["input"].get(tag, ctx["tag"]) if isinstance(err["input"], dict) else ctx["tag"]
        expected, found = "one of " + ctx["expected_tags"], repr(value) if isinstance(value, str) else _describe(value)
    elif kind == "union_tag_not_found":
        tag = ctx["discriminator"].strip("'").removesuffix("()")
        written = _close(tag, err["input"]) if isinstance(err["input"], dict) else None
        parts.append(written or tag)          # a misspelt tag named as written
        expected, found = (f"the required key {tag!r}", f"{written!r} (did you mean {tag!r}?)") if written else \
            ("this key to be present", "nothing")
    else:
        expected = _EXPECTED.get(kind, err["msg"])
    key = ".".join(([path] if path else []) + parts)
    return InputError(file, key, expected, found)


def nested(model: type[BaseModel], value: Any) -> Any:
    """`value` validated as `model` inside another validator (a value of one of several forms); an error is raised
    at its key below the value."""
    try:
        return model.model_validate(value)
    except ValidationError as exc:
        e = input_error(exc, value, "")
        raise refuse(e.expected, e.found, e.key or None) from None


def validate(model: type[BaseModel], data: Any, file: str, path: str = "", **context):
    """`data` (a TOML table at key path `path`) as `model`, its validators given `context` (and the file); any
    problem is an InputError naming the key."""
    try:
        return model.model_validate(data, context={"file": str(file), **context})
    except ValidationError as exc:
        raise input_error(exc, data, str(file), path) from None
