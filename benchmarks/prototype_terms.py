"""What the added physics predicts for the seed's prototype (Table 3,
3 x Thorlabs PK4GA7P1, 150 V ramped in 1 s, no load) against the seed's
7.5 mm simulated and about 7 mm measured: one `sizing evaluate` per added
term, printed as the README's table.

    python benchmarks/prototype_terms.py
"""
from __future__ import annotations

import tempfile
from pathlib import Path

from sizing import api

REPO = Path(__file__).resolve().parents[1]
SEED_SEALS = 'wide_friction = "10 N"       # seed 2.3.3\nnarrow_friction = "0.2 N"\n'


def variants(base: str) -> list[tuple[str, str]]:
    rigid = base.replace('rise_time = "1 s"', 'rise_time = "1 s"\nstructure_stiffness_ratio = 1000')
    seal = lambda name: base.replace(SEED_SEALS, f'seal = "{name}"\n')  # noqa: E731
    air = lambda text, a: text.replace('rise_time = "1 s"', f'rise_time = "1 s"\nair_fraction = {a}')  # noqa: E731
    return [
        ("seed seals 10 N / 0.2 N, rigid structure, no air", rigid),
        ("+ force path (caps and frame at 3 x the stacks)", base),
        ("+ spring-energised PTFE seals at pressure", seal("ptfe-spring-energised")),
        ("+ PTFE O-rings at pressure", seal("ptfe-o-ring")),
        *[(f"+ PTFE O-rings + {a:.1%} air", air(seal("ptfe-o-ring"), a)) for a in (0.005, 0.01, 0.02)],
        ("FKM O-rings at pressure", seal("fkm-o-ring")),
        ("seed seals, rigid, ramped in 3.03 s", rigid.replace('rise_time = "1 s"', 'rise_time = "3.03 s"')),
        ("seed seals, rigid, ramped in 14.55 s", rigid.replace('rise_time = "1 s"', 'rise_time = "14.55 s"')),
        ("seed seals, rigid, ramped in 16.9 s", rigid.replace('rise_time = "1 s"', 'rise_time = "16.9 s"')),
    ]


def main() -> None:
    base = (REPO / "studies" / "seed-table3-prototype.toml").read_text()
    print("| model | free stroke, mm | blocked force, N | output stiffness, N/m |\n|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in variants(base):
            path = Path(tmp) / "design.toml"
            path.write_text(text)
            r = api.evaluate(path)
            w, s = r["simulated"]["worst"], r["static"]
            print(f"| {name} | {w['stroke_m'] * 1e3:.2f} | {s['blocked_force_N']:.1f} | {s['output_stiffness_N_m']:.0f} |")


if __name__ == "__main__":
    main()
