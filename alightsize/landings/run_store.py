"""The run store of a sweep: SQLite in WAL mode at DIR/runs.sqlite (docs/contracts.md), one row per run.

Each finished run is committed on its own, so Ctrl-C, kill -9 or a dying worker loses no finished run; a
re-run skips the runs stored `done` with the same inputs hash, whatever their id (alightsize.landings.sweep).
Columns are added as a study needs them (parameters, summary figures); `wall_s`, `worker` and `finished_at` are
the timing columns, the only ones that may differ between backends.
"""

from __future__ import annotations

import sqlite3
from pathlib import Path

TIMING = ("wall_s", "worker", "finished_at")
_FIXED = ("run_id TEXT PRIMARY KEY", "scene TEXT", "scene_hash TEXT", "status TEXT", "outcome TEXT")


def _ident(name: str) -> str:
    """A column name as an SQL identifier: double-quoted, inner quotes doubled (SQLite's quoting rule), so a
    name from user input (a cell called a"b) never reads as SQL."""
    return '"' + name.replace('"', '""') + '"'


def _sql_type(value) -> str:
    if isinstance(value, bool) or isinstance(value, int):
        return "INTEGER"
    return "REAL" if isinstance(value, float) else "TEXT"


class RunStore:
    """An open runs.sqlite (single writer: the sweep's parent process)."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.db = sqlite3.connect(self.path, isolation_level=None)
        self.db.execute("PRAGMA journal_mode=WAL")
        self.db.execute("PRAGMA synchronous=NORMAL")       # WAL + NORMAL: a commit survives a killed process
        self.db.execute(f"CREATE TABLE IF NOT EXISTS runs ({', '.join(_FIXED)})")
        self.db.execute("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT)")
        self.columns = self._columns()

    def _columns(self) -> list[str]:
        return [r[1] for r in self.db.execute("PRAGMA table_info(runs)")]

    def set_meta(self, **values: str) -> None:
        with self.db:
            self.db.executemany("INSERT OR REPLACE INTO meta VALUES (?, ?)", [(k, str(v)) for k, v in values.items()])

    def done(self) -> dict[str, str]:
        """run_id -> scene_hash of the runs stored `done`."""
        return dict(self.db.execute("SELECT run_id, scene_hash FROM runs WHERE status = 'done'"))

    def delete(self, run_id: str) -> None:
        with self.db:
            self.db.execute("DELETE FROM runs WHERE run_id = ?", (run_id,))

    def put(self, row: dict) -> None:
        """Insert or replace one run and commit it (new columns are added first)."""
        for k, v in row.items():
            if k not in self.columns and v is not None:
                self.db.execute(f"ALTER TABLE runs ADD COLUMN {_ident(k)} {_sql_type(v)}")
                self.columns.append(k)
        keys = [k for k in row if k in self.columns]
        names = ", ".join(_ident(k) for k in keys)
        with self.db:
            self.db.execute(f"INSERT OR REPLACE INTO runs ({names}) VALUES ({', '.join('?' * len(keys))})",
                            [row[k] for k in keys])

    def rows(self, run_ids: list[str] | None = None) -> list[dict]:
        """Stored runs as dicts (all, or those of `run_ids` in that order, looked up by key)."""
        if run_ids is None:
            cur = self.db.execute("SELECT * FROM runs")
            names = [d[0] for d in cur.description]
            return [dict(zip(names, r)) for r in cur]
        found = {}
        wanted = list(dict.fromkeys(run_ids))
        for k in range(0, len(wanted), 500):             # SQLite's bound-parameter limit
            chunk = wanted[k:k + 500]
            cur = self.db.execute(f"SELECT * FROM runs WHERE run_id IN ({', '.join('?' * len(chunk))})", chunk)
            names = [d[0] for d in cur.description]
            found.update((r[0], dict(zip(names, r))) for r in cur)
        return [found[i] for i in run_ids if i in found]

    def close(self) -> None:
        self.db.close()
