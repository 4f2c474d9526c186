"""An end closure solved as an axisymmetric elastic solid (scikit-fem), to
check the plate model where a plate is thick.

The closure is a disc of radius a and thickness t under a uniform pressure
q on its wetted face, in linear elasticity with axial symmetry (u_r, u_z
over the half-section 0 <= r <= a, -t/2 <= z <= t/2; strains d u_r / dr,
d u_z / dz, u_r / r and the shear d u_r / dz + d u_z / dr; every integral
weighted by 2 pi r), on quadratic triangles. Edges:

- ``simply_supported``: u_z = 0 over the edge face, u_r free: the section
  rotates (u_r varies through the thickness) and slides radially, the
  Mindlin plate's w = 0 with a free rotation (a support on one ring of
  nodes would be a line load, singular in the solid);
- ``clamped``: u_r = u_z = 0 over the whole edge face (built in).

What the oil sees is the volume the wetted face sweeps, so the stiffness is
q pi a^2 / w_mean with w_mean the wetted face's mean deflection, as in
``structure.plate_stiffness``. In linear elasticity w_mean = q a / E x
g(t / a, nu), so k = E a pi / g: one solve per (t / a, nu, edge), kept on
disk between runs (``disk_cache``).
A 40 x 8 grid of quadratic triangles is converged to well within 1 %
(tests/physics/test_plate_fe.py doubles it).
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from .. import disk_cache

FE_CHECK_RATIO = 0.3      # thickness over radius above which the plate model is checked against the solid
FE_TOLERANCE = 0.10       # the plate model is used within this of the solid's stiffness, else the solid's
RADIAL_CELLS = 40
THICKNESS_CELLS = 8


def stiffness(a, t, E, nu, edge="simply_supported", radial_cells=RADIAL_CELLS, thickness_cells=THICKNESS_CELLS):
    """Stiffness of a solid disc closure under uniform pressure, referred to
    a piston of its area (N/m): E a pi / g(t/a, nu, edge)."""
    g = _compliance_factor(round(float(t) / float(a), 6), round(float(nu), 6), edge, radial_cells, thickness_cells)
    return float(E) * float(a) * math.pi / g


@lru_cache(maxsize=1024)
@disk_cache.memo("scikit-fem", "scipy", "numpy")
def _compliance_factor(ratio, nu, edge, radial_cells, thickness_cells) -> float:
    """g = w_mean E / (q a) of a disc with a = 1, E = 1, q = 1."""
    from skfem import Basis, BilinearForm, ElementTriP2, ElementVector, FacetBasis, Functional, LinearForm, MeshTri
    from skfem import condense, solve

    mesh = MeshTri.init_tensor(np.linspace(0.0, 1.0, radial_cells + 1),
                               np.linspace(-ratio / 2, ratio / 2, thickness_cells + 1))
    element = ElementVector(ElementTriP2())
    basis = Basis(mesh, element)
    lam, mu = nu / ((1 + nu) * (1 - 2 * nu)), 1.0 / (2 * (1 + nu))

    def strains(u, r):
        return u.grad[0][0], u.grad[1][1], u[0] / r, u.grad[0][1] + u.grad[1][0]

    @BilinearForm
    def elasticity(u, v, w):
        r = w.x[0]
        err, ezz, ett, grz = strains(u, r)
        vrr, vzz, vtt, vrz = strains(v, r)
        trace = err + ezz + ett
        return ((lam * trace + 2 * mu * err) * vrr + (lam * trace + 2 * mu * ezz) * vzz
                + (lam * trace + 2 * mu * ett) * vtt + mu * grz * vrz) * 2 * np.pi * r

    top = mesh.facets_satisfying(lambda x: np.isclose(x[1], ratio / 2))
    wetted = FacetBasis(mesh, element, facets=top)

    @LinearForm
    def pressure(v, w):
        return -v[1] * 2 * np.pi * w.x[0]

    @Functional
    def swept(w):
        return -w["u"][1] * 2 * np.pi * w.x[0]

    K = elasticity.assemble(basis)
    f = pressure.assemble(wetted)
    D = _fixed(mesh, basis, ratio, edge)
    u = solve(*condense(K, f, D=D))
    volume = swept.assemble(wetted, u=wetted.interpolate(u))
    return float(volume / math.pi)          # w_mean = volume / (pi a^2), a = 1


def _fixed(mesh, basis, ratio, edge) -> np.ndarray:
    """The constrained degrees of freedom of the edge condition."""
    if edge == "clamped":
        return basis.get_dofs(lambda x: np.isclose(x[0], 1.0)).all()
    if edge != "simply_supported":
        raise ValueError(f"no finite-element edge {edge!r}: simply_supported or clamped")
    return basis.get_dofs(lambda x: np.isclose(x[0], 1.0)).all("u^2")


CHECK_GRID = (0.3, 0.4, 0.5, 0.6, 0.8, 1.0)   # t / a where the solid is solved; the ratio between is interpolated


def model_ratio(ratio, nu, edge) -> float:
    """Plate model stiffness (``structure.plate_stiffness``, Mindlin) over
    the solid's, at thickness over radius ``ratio`` (FE_CHECK_RATIO and
    above; interpolated linearly between solids solved on CHECK_GRID, each
    once per Poisson ratio and edge)."""
    grid = _ratio_grid(round(float(nu), 6), edge)
    return float(np.interp(float(ratio), CHECK_GRID, grid))


@lru_cache(maxsize=64)
def _ratio_grid(nu, edge) -> tuple:
    from . import structure
    return tuple(float(structure.plate_stiffness(1.0, r, 1.0, nu, edge)) / stiffness(1.0, r, 1.0, nu, edge)
                 for r in CHECK_GRID)


def checked_stiffness(k_model, ratio):
    """The stiffness a design uses: the plate model's within FE_TOLERANCE of
    the solid's (``ratio`` = model / solid; NaN where not checked), else the
    solid's, k_model / ratio."""
    k_model, ratio = np.asarray(k_model, float), np.asarray(ratio, float)
    off = np.isfinite(ratio) & (np.abs(ratio - 1.0) > FE_TOLERANCE)
    return np.where(off, k_model / np.where(off, ratio, 1.0), k_model)
