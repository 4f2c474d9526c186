"""One set of counts: every count on the report's first screen (the answer,
the requirements paragraph, what was ruled out) is read from results.json
``summary.counts``; the ruled-out section never reads 0 over a count."""
from __future__ import annotations

import json
import re

from ..conftest import FAST_REQUIREMENTS, run_cli


def test_the_first_screen_counts_agree_with_results_json(tmp_path):
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS.replace("max_stacks = 2", "max_stacks = 6"))
    code, _, err = run_cli("solve", req, "--out", tmp_path / "out", "--quiet", "--fast")
    assert code == 0, err
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    html = (tmp_path / "out" / "report.html").read_text()
    counts = results["summary"]["counts"]
    ph = counts["piezohydraulic"]
    assert ph["ruled_out_before_sizing"] > 0       # else the check below checks nothing
    first = html[:html.index("<h2>Verdict per technology</h2>")]
    said = {m.group(2): int(m.group(1).replace(",", "")) for m in re.finditer(
        r"([\d,]+) (piezohydraulic combinations|ruled out before sizing|sized by geometric programs|"
        r"designs verified by simulation)", first)}
    assert said == {"piezohydraulic combinations": ph["combinations"], "ruled out before sizing": ph["ruled_out_before_sizing"],
                    "sized by geometric programs": ph["sized"], "designs verified by simulation": ph["simulated"]}
    left = re.search(r"<b>piezohydraulic</b>: ([\d,]+) of ([\d,]+) combinations ruled out before sizing, ([\d,]+) designs",
                     first)
    assert left and [int(g.replace(",", "")) for g in left.groups()] == [
        ph["ruled_out_before_sizing"], ph["combinations"], ph["left_out"]]
    # the section further down: the same count, never a false zero
    section = html[html.index("<h2>Ruled out before sizing</h2>"):]
    assert f"{ph['ruled_out_before_sizing']:,} piezohydraulic combinations were ruled out before sizing" in section
    assert "<p>0 combinations were ruled out" not in section
    # results.json agrees with itself: the counts by reason add up
    by_reason = sum(results["summary"]["ruled_out_by_technology"]["piezohydraulic"].values())
    assert by_reason == ph["ruled_out_before_sizing"] + ph["left_out"]
    assert counts["ranked"] == len(results["candidates"])
