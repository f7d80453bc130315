r"""Tangential contact on an elastic layer bonded to a rigid base (issue 34, item 3): the layer's tangential punch
problem solved exactly (within the decoupled problem stated below), tabulated against ``a/h``, and what it makes of the
MDR's tangential springs and of the slip cap (13).

The tangential punch problem
----------------------------
A rigid circular punch of radius ``a`` sticks to the layer's top and is moved tangentially by ``u₀`` (along ``x``);
the top carries no normal traction (``σ_zz = 0`` everywhere: the tangential problem decoupled from the normal one, as
the MDR and Cattaneo–Mindlin treat it); the base is bonded. In Fourier space (wave number ``ξ``) the top's tangential
response to a tangential traction splits into a *longitudinal* part (along ``ξ``: the plane-strain P–SV problem with
``σ_zz = 0``) and a *transverse* part (across ``ξ``: anti-plane shear)

.. math:: \hat u_L = \frac{(1-\nu)\,C_L(\xi h)}{G\xi}\,\hat q_L, \qquad
          \hat u_T = \frac{C_T(\xi h)}{G\xi}\,\hat q_T,

.. math:: C_L(t) = \frac{2\kappa\sinh 2t + 4t}{2\kappa\cosh 2t + 1 + \kappa^2 + 4t^2}, \qquad C_T(t) = \tanh t,
          \qquad \kappa = 3 - 4\nu \quad (T1)

(:func:`tangential_compliance`; derived from the Papkovich–Neuber solution in
:mod:`mdr_events.theory.layer_tangential_symbolic`, which also recovers the normal compliance of
:func:`mdr_events.theory.layer.compliance_function` with ``−4t`` in place of ``+4t``). Both tend to 1 as ``t → ∞``:
the half-space's ``(1 − ν k̂k̂ᵀ)/(Gξ)``. The punch's traction is ``q_x + i q_y = Q₀(r) + Q₂(r) e^{2iθ}``; with the
representations ``Q̂₀(ξ) = ∫₀ᵃ φ₀(t) cos ξt dt`` (order-0 Hankel transform) and ``Q̂₂(ξ) = ∫₀ᵃ χ(t) cos ξt dt``
(order 2, with ``∫₀ᵃ χ = 0``: then ``Q₂`` vanishes outside the punch), the order-0 Abel operator turns
``U₀ = u₀`` and the order-2 one turns ``U₂ = 0`` (``r < a``) into equations on ``[0, a]``; in the combinations
``P = Θ₀ + X`` and ``Q = Θ₀ − X`` (``φ₀, χ = (4Gu₀/(π(2 − ν))) Θ₀, X``) they decouple into two equations of the
Lebedev–Ufliand type (the normal punch's (L1) of :mod:`mdr_events.theory.layer`), ``λ = a/h``:

.. math:: \Psi_m(\tau) - \frac{\lambda}{\pi}\int_0^1 \Psi_m(\sigma)\,[k_m(\lambda(\tau-\sigma))
          + k_m(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = 1, \qquad
          k_m(v) = \int_0^\infty [1 - C_m(u)]\cos(uv)\,\mathrm{d}u, \quad m = L, T \quad (T2)

(:func:`tangential_kernel`, :func:`solve_tangential_punch`), and the constraint ``∫X = 0`` fixes the constant of the
order-2 equation. :func:`contact_displacement` checks the reduction without it: the top's displacement under the
solved traction, by direct Hankel quadrature of (T1), is ``u₀`` and uniform inside the punch (to about 1e-15 at
``a/h = 0.3, 1, 3``, ``ν = 0, 0.3, 0.5``). The force ``F_x = 2π Q̂₀(0)`` gives the tangential stiffness

.. math:: K_t(a) = 2G^* a\,\Phi_t(\lambda), \qquad
          \frac{2-\nu}{\Phi_t} = \frac{1-\nu}{\Phi_L} + \frac{1}{\Phi_T}, \qquad \Phi_m = \int_0^1 \Psi_m
          \quad (T3)

(``G* = 4G/(2 − ν)``; ``Φ_L = Φ_T = 1``, ``K_t = 8Ga/(2 − ν)`` on the half-space). Each ``Φ_m`` obeys the edge
identity of the normal punch, ``d(λΦ_m)/dλ = Ψ_m(1)²``, so the slope is exact from the edge values:

.. math:: K_t'(a) = 2G^*\,\Sigma_t(\lambda), \qquad \Sigma_t = \frac{\Phi_t^2}{2-\nu}
          \Big[(1-\nu)\frac{\Psi_L(1)^2}{\Phi_L^2} + \frac{\Psi_T(1)^2}{\Phi_T^2}\Big] \quad (T4)

The thin layer is a Winkler foundation in shear (``û = (h/G) q̂``): ``K_t → π a² G/h``, approached at first order in
``h/a`` (an edge boundary layer of width ``h``).

A frictionless base has no tangential stiffness at the scale of the layer: ``C_T = coth t`` and
``(1 − ν)C_L = (1 − ν)(cosh 2t + 1)/(sinh 2t + 2t)`` grow as ``1/t`` for ``t → 0`` (the layer slides on its base as a
plate in plane stress), so the displacement of a punch under a net force diverges as ``∫ dξ/ξ``: logarithmically in
the layer's lateral extent ``L`` (``u₀ ∝ F_x ln(L/a)/(G h)``); ``K_t = 0`` for an unbounded layer. The
functions below refuse such a layer, naming it (:func:`check_bonded`).

What the decoupling neglects
----------------------------
The exact problem of a sticking punch couples the two: a shear traction moves the top normally and a pressure moves
it tangentially, by the off-diagonal compliance ``C_zx`` (:func:`coupling_ratio`: ``m = |C_zx|/sqrt(C_zz C_xx)``,
``(1 − 2ν)/(2(1 − ν))`` on the half-space, 0 at ``ν = 0.5``; on a bonded layer non-zero even at ``ν = 0.5``, rising
to ``√3/2`` in the thin incompressible limit ``t → 0``). Minimising the complementary energy over the pressure as well
bounds the effect on the tangential stiffness: ``K_t ≤ K_t,coupled ≤ K_t/(1 − m_max²)``
(:func:`coupling_bound`).

The generalized MDR's tangential springs and caps
--------------------------------------------------
A flat punch moved by ``u₀`` is ``K_t(a) u₀ = ∫₋ₐᵃ k_t(x) u₀ dx``, so the springs' tangential stiffness per width is
``k_t(x) = K_t'(|x|)/2 = G* Σ_t(|x|/h)`` (:func:`tangential_spring_stiffness_density`; ``G*`` on the half-space).
By the superposition of incremental sticking punches this is exact for a sticking contact with any history of the
radius and of ``u`` (within the decoupled problem), as on the half-space. The cap (12)–(13), "every spring in contact
shifted by the same ``ū`` when the contact slides stationarily, the mean shear stress then ``τ0``", becomes
``ū(a) = π a² τ0 / K_t(a)`` (:func:`sliding_cap`); Coulomb's cap becomes ``μ (k(x)/k_t(x)) (d − g(x))``
(:func:`coulomb_cap`). Both give exactly the fully sliding forces ``π a² τ0`` and ``μ F_N``; which springs slide
first (partial slip) is an approximation on a layer (the normal and tangential punches' tractions no longer share one
radial profile, and the tangential one is anisotropic at the edge: :attr:`TangentialPunchSolution.edge_anisotropy`).

Numerics: the same as the normal punch's (Gauss–Legendre Nyström with :func:`mdr_events.theory.layer.nystrom_nodes`,
spectral; the kernels from a Gauss–Legendre quadrature of ``1 − C_m`` evaluated without cancellation, kept as
piecewise Chebyshev interpolants), tables of ``Φ_L, Φ_T, Ψ_L(1), Ψ_T(1)`` against ``ln λ`` (quintic splines of the
logarithms, within 1e-8 of direct solves), cached on disk (:func:`tangential_table_cache_path`).

Modules
-------
The code lives in :mod:`mdr_events.theory.layer` beside the normal punch's, one idea per module:
``tangential_compliance`` (``C_m`` (T1), the kernels ``k_m``, :func:`check_bonded`), ``tangential_coupling``
(the coupling and its bound), ``tangential_punch`` (the Nyström solve of (T2): :class:`TangentialPunchSolution`),
``tangential_tables`` (the factors against ``a/h``, cached on disk: :class:`TangentialTable`),
``tangential_displacement`` (the check of the reduction by direct Hankel quadrature),
``tangential_relations`` (``K_t``, ``k_t``, the caps); this module re-exports their public names.
"""

from __future__ import annotations

from mdr_events.theory.layer.tangential_compliance import (LAMBDA_MAX, MODES, check_bonded, tangential_compliance,
                                                           tangential_kernel)
from mdr_events.theory.layer.tangential_coupling import coupling_bound, coupling_ratio
from mdr_events.theory.layer.tangential_displacement import contact_displacement
from mdr_events.theory.layer.tangential_punch import TangentialPunchSolution, solve_tangential_punch
from mdr_events.theory.layer.tangential_relations import (coulomb_cap, sliding_cap, tangential_punch_stiffness,
                                                          tangential_punch_stiffness_slope,
                                                          tangential_spring_stiffness_density)
from mdr_events.theory.layer.tangential_tables import (LAMBDA_MIN, TABLE_STEP, TangentialTable, tangential_table,
                                                       tangential_table_cache_path)

__all__ = ["MODES", "LAMBDA_MAX", "LAMBDA_MIN", "TABLE_STEP", "check_bonded", "tangential_compliance",
           "coupling_ratio", "coupling_bound", "tangential_kernel", "TangentialPunchSolution", "solve_tangential_punch",
           "TangentialTable", "tangential_table", "tangential_table_cache_path", "tangential_punch_stiffness",
           "tangential_punch_stiffness_slope", "tangential_spring_stiffness_density", "sliding_cap", "coulomb_cap",
           "contact_displacement"]
