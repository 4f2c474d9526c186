"""Cut the real measurement source/run.csv (Chandra et al., APL 2023; MIT
licence, see source/README.md and source/LICENSE) into three runs for
`sizing fit hysteresis`:

    runs/t03-07.csv   3.3-7 s: the excitation starting from rest (first 3.7 cycles)
    runs/t07-09.csv   7-9 s:   two full cycles, the authors' fitting window
    runs/t09-10.csv   9-10 s:  the last cycle

Rows are copied unchanged (time stays absolute; the fit does not need
t = 0 at the start). Run from anywhere:
    python studies/piezo-bipolar/make_runs.py [PATH/TO/run.csv]
A missing or unreadable source exits 2 with one line naming it.
"""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCE = Path(sys.argv[1]) if len(sys.argv) > 1 else HERE / "source" / "run.csv"
WINDOWS = {"t03-07": (3.3, 7.0), "t07-09": (7.0, 9.0), "t09-10": (9.0, 10.0)}
HEADER = "time_s,voltage_V,position_m"


def fail(message: str) -> None:
    print(f"make_runs.py: {message}", file=sys.stderr)
    sys.exit(2)


try:
    lines = SOURCE.read_text().splitlines()
except OSError as exc:
    fail(f"{SOURCE}: cannot read the measurement ({exc.strerror or exc}); it ships as "
         f"studies/piezo-bipolar/source/run.csv (see source/README.md), or pass its path")
if not lines or lines[0].strip() != HEADER:
    fail(f"{SOURCE}: expected the header {HEADER!r}, got {lines[0].strip()[:60] if lines else 'an empty file'!r}")
header, rows = lines[0], lines[1:]
(HERE / "runs").mkdir(exist_ok=True)
for name, (t0, t1) in WINDOWS.items():
    try:
        keep = [r for r in rows if t0 - 1e-9 <= float(r.split(",", 1)[0]) < t1 - 1e-9]
    except ValueError:
        fail(f"{SOURCE}: a time_s value is not a number")
    (HERE / "runs" / f"{name}.csv").write_text("\n".join([header, *keep]) + "\n")
    print(f"{name}: {len(keep)} rows")
