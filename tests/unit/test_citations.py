"""Shipped files cite AFFDL-TR-66-33 the way a reader holding the published report can follow (section, table,
equation, figure, appendix), never by line of a private transcription, and hold no absolute path of a machine."""

import re
from pathlib import Path

from conftest import ROOT

SHIPPED = ("alightsize", "alightsize_sim", "examples", "templates", "docs", "tests", "benchmarks", "pyproject.toml",
           "README.md")
SUFFIXES = {".py", ".toml", ".md", ".csv", ".j2", ".txt", ".json", ".yaml", ".yml", ".cfg", ".ini", ".html"}
# "line 1085", "lines 986-993", "l. 1234" (3 or 4 digits: the transcription runs to 9,487 lines); "line 12 of x.csv"
# style messages about a user's own file have fewer digits or name the file, so they do not match.
TRANSCRIPTION = re.compile(r"(?<![\w.])(?:[Ll]ines?|l\.)\s+~?\d{3,4}\b(?!\s+of\s+(?:the\s+)?[\w./-]+\.\w+)")
MACHINE_PATH = re.compile(r"(?<![\w.])/work/")


def _files():
    for top in SHIPPED:
        path = ROOT / top
        paths = [path] if path.is_file() else path.rglob("*")
        for p in paths:
            if p.is_file() and p.suffix in SUFFIXES and "__pycache__" not in p.parts and p != Path(__file__):
                yield p


def _hits(pattern: re.Pattern) -> list[str]:
    out = []
    for p in _files():
        for n, line in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            if pattern.search(line):
                out.append(f"{p.relative_to(ROOT)}:{n}: {line.strip()[:100]}")
    return out


def test_no_transcription_line_citations():
    assert _hits(TRANSCRIPTION) == []


def test_no_absolute_machine_paths():
    assert _hits(MACHINE_PATH) == []


def test_the_patterns_catch_what_they_guard_against():
    for text in ("(FUNEV, line 6692)", "lines 986-993 of the report", "l. 1234", "Line 1221 says", "(line ~8118)"):
        assert TRANSCRIPTION.search(text), text
    for text in ("runs.csv line 2, run", "App. VII, telescoping subroutine FORCE", "Table 3 row 1", "deadline 30"):
        assert not TRANSCRIPTION.search(text), text
    assert MACHINE_PATH.search('SOURCE = "/work/shared/reference/x.txt"')
