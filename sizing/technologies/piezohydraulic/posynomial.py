"""Posynomials as plain data: the sizing program's expressions expanded
into monomials, so that a batch of combinations can be evaluated and
solved with numpy (``batch_gp.py``) from the very code that writes the
program for cvxpy (``convex.Program``).

A posynomial is a sum of monomials c prod_j z_j^a_j over named symbols
z_j (the program's variables and parameters) with c > 0. ``Posynomial``
supports what the program's expressions use: +, *, / by a monomial, ** of
a monomial (any real power) or of a posynomial (a positive integer), and
``<=`` which, as cvxpy's ``a <= b`` does, states a constraint; here it is
the posynomial a / b (b a monomial), to be kept <= 1.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


class Posynomial:
    """sum_k c_k prod_j z_j^a_kj; ``terms`` maps the exponents (a tuple of
    (symbol, power) pairs, sorted) to the coefficient c_k."""

    __slots__ = ("terms",)

    def __init__(self, terms: dict):
        self.terms = terms

    @classmethod
    def symbol(cls, name: str) -> "Posynomial":
        return cls({((name, 1.0),): 1.0})

    @classmethod
    def constant(cls, value: float) -> "Posynomial":
        if not value > 0:
            raise ValueError(f"a posynomial's coefficients are positive, got {value!r}")
        return cls({(): float(value)})

    @staticmethod
    def _of(other) -> "Posynomial":
        return other if isinstance(other, Posynomial) else Posynomial.constant(other)

    @property
    def is_monomial(self) -> bool:
        return len(self.terms) == 1

    def __add__(self, other):
        out = dict(self.terms)
        for key, c in self._of(other).terms.items():
            out[key] = out.get(key, 0.0) + c
        return Posynomial(out)

    __radd__ = __add__

    def __mul__(self, other):
        other = self._of(other)
        out: dict = {}
        for ka, ca in self.terms.items():
            for kb, cb in other.terms.items():
                key = _merge(ka, kb, 1.0)
                out[key] = out.get(key, 0.0) + ca * cb
        return Posynomial(out)

    __rmul__ = __mul__

    def __truediv__(self, other):
        return self * self._of(other) ** -1

    def __rtruediv__(self, other):
        return self._of(other) * self ** -1

    def __pow__(self, p):
        p = float(p)
        if self.is_monomial:
            (key, c), = self.terms.items()
            return Posynomial({tuple((s, a * p) for s, a in key if a * p != 0): c ** p})
        if p != int(p) or p < 1:
            raise ValueError(f"a posynomial of {len(self.terms)} terms to the power {p} is not a posynomial")
        out = self
        for _ in range(int(p) - 1):
            out = out * self
        return out

    def __le__(self, other):
        other = self._of(other)
        if not other.is_monomial:
            raise ValueError("a posynomial is bounded by a monomial")
        return self / other


def _merge(a: tuple, b: tuple, sign: float) -> tuple:
    powers = dict(a)
    for s, p in b:
        powers[s] = powers.get(s, 0.0) + sign * p
    return tuple(sorted((s, p) for s, p in powers.items() if p != 0))


@dataclass(frozen=True)
class Layout:
    """Posynomials laid out as arrays over a fixed variable and parameter
    order: term k of posynomial ``group[k]`` is
    exp(log_coefficient[k] + parameter_powers[k] @ log(theta) + variable_powers[k] @ y)
    with y = log(variables)."""

    variable_powers: np.ndarray        # (terms, variables)
    parameter_powers: np.ndarray       # (terms, parameters)
    log_coefficient: np.ndarray        # (terms,)
    group: np.ndarray                  # (terms,) index of the posynomial each term belongs to
    starts: np.ndarray                 # (posynomials,) first term of each posynomial

    @classmethod
    def of(cls, posynomials: list[Posynomial], variables: list[str], parameters: list[str]) -> "Layout":
        vi = {n: i for i, n in enumerate(variables)}
        pi = {n: i for i, n in enumerate(parameters)}
        rows_v, rows_p, logc, group, starts = [], [], [], [], []
        for g, posy in enumerate(posynomials):
            starts.append(len(logc))
            for key, c in posy.terms.items():
                v, p = np.zeros(len(variables)), np.zeros(len(parameters))
                for s, a in key:
                    if s in vi:
                        v[vi[s]] = a
                    elif s in pi:
                        p[pi[s]] = a
                    else:
                        raise KeyError(f"unknown symbol {s!r}")
                rows_v.append(v)
                rows_p.append(p)
                logc.append(math.log(c))
                group.append(g)
        return cls(np.array(rows_v), np.array(rows_p), np.array(logc), np.array(group, dtype=np.intp),
                   np.array(starts, dtype=np.intp))

    @property
    def size(self) -> int:
        return len(self.starts)
