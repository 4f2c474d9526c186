"""The DC parts search at catalog scale: motor x mountable gear (or none) x
screw x drive, pruned without losing a feasible combination.

A few hundred datasheet motors, each with up to a few hundred gearheads,
times the screws and drives, make millions of combinations; the static
screen (``dc_parts.static_screen``) runs only on those no cheaper argument
rules out. Each argument is a necessary condition of a margin the screen
computes, so a combination it removes fails that margin in the screen too
(``tests/engine/test_dc_search.py`` compares with brute force):

1. one part alone (exact): a motor, gear or screw rated below the ambient
   (``temperature``), a winding limit below it (``winding_temperature``), a
   drive rated below where it sits (``drive_temperature``); a screw that
   buckles under the blocked force, wears out before REQUIRED_LIFE_H, has a
   static safety C0 / F below the required factor at the required force (the
   design's peak force is at least that), or whose own speed limit is below
   the required speed at any ratio (v <= n_screw l / 2 pi);
2. motor x screw x drive (bound): with the most favourable values the
   design can have (k_t at the ambient, not derated further by the winding;
   the resistance at the ambient, not hotter; a gear efficiency of 1; the
   full bus voltage), the blocked force needs N >= F l / (2 pi eta T_peak)
   and the speed under load puts N between the roots of the voltage
   equation (``dc_parts.ratio_interval``); gearheads outside are out
   (``blocked_force`` or ``speed``), found per motor by bisection over its
   gearheads sorted by ratio;
3. gear x screw (exact): the gear's intermittent output torque caps the
   force (``blocked_force``), its continuous torque the holding load
   (``gear_torque``), its input speed limit the speed (``speed``).

The survivors are screened in chunks; an infeasible one counts under the
margin it misses most. The statically feasible ones (and, when there are
few, the closest to feasible) go on to the simulation; those beyond its
budget count as ``not simulated``. Nothing ruled out gets a record: the
counts by reason are returned instead.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...physics import motor as motor_phys
from ...physics import screw as screw_phys
from . import parts as dc_parts
from .parts import PartArrays, REQUIRED_LIFE_H, mountable, part_lists, parts_at

CHUNK = 100_000          # combinations per static-screen chunk
NEAR_KEPT = 64           # infeasible combinations kept (closest first) for the simulation's minimum


@dataclass
class SearchResult:
    parts: PartArrays                 # feasible survivors, then the closest infeasible ones
    n_feasible: int                   # statically feasible among ``parts``
    combinations: int                 # all combinations of the catalog
    ruled_out: dict = field(default_factory=dict)   # reason -> count, for the combinations not in ``parts``
    screened: int = 0                 # combinations that reached the static screen


def _add(counts: dict, reason: str, n) -> None:
    n, reason = int(n), str(reason)
    if n:
        counts[reason] = counts.get(reason, 0) + n


def search(catalog, req, loads) -> SearchResult:
    lists = part_lists(catalog)
    M, S, G, D = lists
    gears_of = mountable(catalog)
    if not (M and S and D):
        empty = parts_at(lists, *(np.zeros(0, int) for _ in range(4)))
        return SearchResult(empty, 0, 0)
    cols = dc_parts._columns(lists)
    c = lambda name: cols[name]
    r, o = req.requirements, req.options
    T, F_req, v_req = r.max_temperature, r.blocked_force, r.speed
    F_load = max(loads) if loads else 0.0
    nS, nD = len(S), len(D)
    per_motor = np.array([len(g) + 1 for g in gears_of])
    total = int(per_motor.sum()) * nS * nD
    counts: dict = {}

    # 1. parts alone
    m_reason = np.where(c("motor_max_temperature") < T, "temperature",
                        np.where(c("motor_max_winding_temperature") < T, "winding_temperature", ""))
    lead, eta_s = c("screw_lead"), c("screw_efficiency")
    screw_len = dc_parts.TRAVEL_FACTOR * r.stroke + dc_parts.SCREW_EXTRA_LENGTH
    P_cr = screw_phys.buckling_load(c("screw_elastic_modulus"), c("screw_diameter"), screw_len)
    rev_per_s = 2 * r.stroke / lead * req.duty.strokes_per_second
    life_h = screw_phys.l10_revolutions(c("screw_dynamic_load_rating"), F_load) / rev_per_s / 3600.0
    s_reason = np.select(
        [c("screw_max_temperature") < T, P_cr < F_req, life_h < REQUIRED_LIFE_H,
         c("screw_static_load_rating") / F_req < dc_parts.STATIC_SAFETY_REQUIRED,
         screw_phys.output_speed(c("screw_max_speed"), lead) < v_req],
        ["temperature", "buckling", "screw_life", "static_safety", "speed"], "")
    drive_ambient = o.electronics_bay_temperature if o.amplifier_location == "bay" else T
    d_reason = np.where(c("drive_max_temperature") < drive_ambient, "drive_temperature", "")
    for reason in set(m_reason) - {""}:
        _add(counts, reason, per_motor[m_reason == reason].sum() * nS * nD)
    good_m = np.flatnonzero(m_reason == "")
    good_s = np.flatnonzero(s_reason == "")
    good_d = np.flatnonzero(d_reason == "")
    n_good = int(per_motor[good_m].sum())
    for reason in set(s_reason) - {""}:
        _add(counts, reason, n_good * np.sum(s_reason == reason) * nD)
    _add(counts, "drive_temperature", n_good * len(good_s) * (nD - len(good_d)))

    # 2. motor x screw x drive: the ratio bounds, gearheads by bisection
    g_ratio = c("gear_ratio")
    mi, si, di = (a.ravel() for a in np.meshgrid(good_m, good_s, good_d, indexing="ij"))
    kt = motor_phys.torque_constant_at(c("motor_torque_constant")[mi],
                                       np.minimum(c("motor_torque_constant_temperature_coefficient")[mi], 0.0), T)
    t_peak = np.minimum(kt * c("drive_peak_current")[di], c("motor_peak_torque")[mi])
    r_cold = motor_phys.resistance_at(c("motor_winding_resistance")[mi],
                                      c("motor_resistance_temperature_coefficient")[mi], T)
    ke = c("motor_back_emf_constant")[mi]
    n_force = F_req * lead[si] / (2 * np.pi * eta_s[si] * t_peak)
    lo, hi = dc_parts.ratio_interval(kt, ke, r_cold, t_peak / kt, lead[si], eta_s[si], c("drive_bus_voltage")[di],
                                     c("motor_max_speed")[mi], 0.0, F_load, v_req)
    lo = np.maximum(lo, n_force)
    keep_m, keep_s, keep_g, keep_d = [], [], [], []
    direct = (n_force <= 1.0 + 1e-9) & (lo <= 1.0 + 1e-9) & (hi >= 1.0 - 1e-9)
    _add(counts, "blocked_force", np.sum(~direct & (n_force > 1.0 + 1e-9)))
    _add(counts, "speed", np.sum(~direct & (n_force <= 1.0 + 1e-9)))
    keep_m.append(mi[direct]); keep_s.append(si[direct]); keep_g.append(np.zeros(int(direct.sum()), int))
    keep_d.append(di[direct])
    start = 0                 # per motor: its gearheads sorted by ratio, bisected
    for m in good_m:
        stop = start + len(good_s) * len(good_d)
        gears = gears_of[m]
        if len(gears):
            ratios = g_ratio[gears + 1]
            below = np.searchsorted(ratios, n_force[start:stop] * (1 - 1e-9), "left")
            a = np.maximum(np.searchsorted(ratios, lo[start:stop] * (1 - 1e-9), "left"), below)
            b = np.maximum(np.searchsorted(ratios, hi[start:stop] * (1 + 1e-9), "right"), a)
            _add(counts, "blocked_force", below.sum())
            _add(counts, "speed", (len(gears) - below).sum() - (b - a).sum())
            n = b - a
            if n.sum():
                rows = np.repeat(np.arange(start, stop), n)
                offset = np.arange(int(n.sum())) - np.repeat(np.cumsum(n) - n, n)
                keep_m.append(mi[rows]); keep_s.append(si[rows]); keep_d.append(di[rows])
                keep_g.append(gears[np.repeat(a, n) + offset] + 1)
        start = stop
    im, isc, ig, idr = (np.concatenate(k).astype(int) for k in (keep_m, keep_s, keep_g, keep_d))

    # 3. gear x screw
    t_need = screw_phys.torque_for_force(F_req, lead[isc], eta_s[isc])
    g_reasons = ("temperature", "blocked_force", "gear_torque", "speed")
    # each row's first failing check as an index into g_reasons (0: none);
    # integer codes, counted by bincount: half a million rows of strings
    # cost a tenth of a second to compare
    g_code = np.select(
        [c("gear_max_temperature")[ig] < T, c("gear_max_output_torque")[ig] < t_need * (1 - 1e-12),
         c("gear_continuous_output_torque")[ig] < screw_phys.torque_for_force(F_load, lead[isc], eta_s[isc]),
         screw_phys.output_speed(c("gear_max_input_speed")[ig], lead[isc], g_ratio[ig]) < v_req],
        np.arange(1, len(g_reasons) + 1), 0)
    for reason, n in zip(g_reasons, np.bincount(g_code, minlength=len(g_reasons) + 1)[1:]):
        _add(counts, reason, n)
    ok = g_code == 0
    im, isc, ig, idr = im[ok], isc[ok], ig[ok], idr[ok]

    # 4. the static screen, in chunks
    feasible, near, near_worst, near_reason = [], np.zeros(0, int), np.zeros(0), np.zeros(0, object)
    for begin in range(0, len(im), CHUNK):
        sl = slice(begin, begin + CHUNK)
        p = parts_at(lists, im[sl], isc[sl], ig[sl], idr[sl])
        _, _, margins = dc_parts.static_screen(p, req, loads)
        names = list(margins)
        Mx = np.nan_to_num(np.vstack([margins[k] for k in names]), nan=-np.inf, posinf=np.inf)
        worst = Mx.min(axis=0)
        good = worst >= 0
        feasible.append(begin + np.flatnonzero(good))
        bad = np.flatnonzero(~good)
        missed = Mx[:, bad].argmin(axis=0)
        reason = np.array(names, dtype=object)[missed]
        for name, n in zip(names, np.bincount(missed, minlength=len(names))):
            _add(counts, name, n)
        pool = np.concatenate([near, begin + bad])
        pool_worst = np.concatenate([near_worst, np.maximum(worst[bad], -1e300)])
        pool_reason = np.concatenate([near_reason, reason])
        order = np.argsort(-pool_worst, kind="stable")[:NEAR_KEPT]
        near, near_worst, near_reason = pool[order], pool_worst[order], pool_reason[order]
    feasible = np.concatenate(feasible) if feasible else np.zeros(0, int)
    for name in near_reason:             # kept for the simulation's minimum: no longer ruled out
        counts[name] -= 1
        if not counts[name]:
            del counts[name]
    kept = np.concatenate([feasible, near]).astype(int)
    parts = parts_at(lists, im[kept], isc[kept], ig[kept], idr[kept])
    return SearchResult(parts, len(feasible), total, counts, screened=len(im))
