"""Pure physics: functions and small dataclasses over SI floats and numpy
arrays, vectorised over candidates. No I/O."""
