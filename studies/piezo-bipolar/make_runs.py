"""Cut the real measurement ../shared/data/piezo-bipolar-150V-1Hz/run.csv
(Chandra et al., APL 2023; MIT licence, see that folder's README and
LICENSE) into three runs for `sizing fit hysteresis`:

    runs/t03-07.csv   3.3-7 s: the excitation starting from rest (first 3.7 cycles)
    runs/t07-09.csv   7-9 s:   two full cycles, the authors' fitting window
    runs/t09-10.csv   9-10 s:  the last cycle

Rows are copied unchanged (time stays absolute; the fit does not need
t = 0 at the start). Run from the repository root:
    python studies/piezo-bipolar/make_runs.py [PATH/TO/run.csv]
"""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCE = Path(sys.argv[1]) if len(sys.argv) > 1 else HERE.parents[2] / "shared/data/piezo-bipolar-150V-1Hz/run.csv"
WINDOWS = {"t03-07": (3.3, 7.0), "t07-09": (7.0, 9.0), "t09-10": (9.0, 10.0)}

lines = SOURCE.read_text().splitlines()
header, rows = lines[0], lines[1:]
(HERE / "runs").mkdir(exist_ok=True)
for name, (t0, t1) in WINDOWS.items():
    keep = [r for r in rows if t0 - 1e-9 <= float(r.split(",", 1)[0]) < t1 - 1e-9]
    (HERE / "runs" / f"{name}.csv").write_text("\n".join([header, *keep]) + "\n")
    print(f"{name}: {len(keep)} rows")
