"""What a kind of indenter makes of a layer's normal springs in the continuum (:class:`~.layer_media.LayerMedium`):
the exponent of the profile's table, the branch its radius follows and the normal force, looked up by the indenter's
type (:data:`LAYER_NORMALS`).

==========================  ===========================================================================================
kind                        the normal springs
==========================  ===========================================================================================
:class:`ProfileNormal`      a paraboloid or power law: the layer's profile ``g = κₙ c aⁿ γₙ(a/h)``, the branch
                            :class:`~.layer_branch.LayerBranch`, ``F_N = F₀(a) + K(a)(d − g(a))``
:class:`PunchNormal`        the flat punch: ``g = 0`` under the face, the branch
                            :class:`~.layer_punch_branch.LayerPunchBranch` (the face held, then receding), ``F_N =
                            K(a) d`` (``layer_flat_punch_force``)
==========================  ===========================================================================================
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from mdr_events.contact.indenters import FlatPunch, Paraboloid, PowerLaw
from mdr_events.contact.layer import Layer
from mdr_events.parameters import Parameters

__all__ = ["ProfileNormal", "PunchNormal", "LAYER_NORMALS"]


class ProfileNormal:
    """A paraboloid or power law on a layer: its profile's table, :class:`~.layer_branch.LayerBranch`, (10)."""

    @staticmethod
    def exponent(indenter) -> float:
        """The power ``n`` of the profile (its table's).

        Parameters
        ----------
        indenter : Paraboloid or PowerLaw
            The indenter.

        Returns
        -------
        float
            ``n``.
        """
        from mdr_events.theory.layer.relations import _power_law

        return _power_law(indenter)[1]

    @staticmethod
    def branch(params: Parameters, work: float, indenter, layer: Layer, factors):
        """The branch of ``work``.

        Parameters
        ----------
        params : Parameters
            The material.
        work : float
            The work of adhesion (J/m²).
        indenter : Paraboloid or PowerLaw
            The indenter.
        layer : Layer
            The layer.
        factors : NormalFactors
            The layer's normal factors.

        Returns
        -------
        LayerBranch
            The branch.
        """
        from .layer_branch import LayerBranch

        return LayerBranch(params, work, indenter, layer, factors)

    @classmethod
    def spring_factors(cls, params: Parameters, indenter, layer: Layer):
        """``g``, ``k`` and ``k_t`` of the springs as the per-spring route reads them (:mod:`.play_springs`): the
        layer's profile ``g = κₙ c xⁿ γₙ(x/h)`` (L4) of a paraboloid or power law, the flat punch's ``0`` under its
        face (``+inf`` beyond), and the tables' stiffnesses.

        Parameters
        ----------
        params : Parameters
            The material.
        indenter : Paraboloid, PowerLaw or FlatPunch
            The indenter.
        layer : Layer
            The layer (bonded base).

        Returns
        -------
        SpringFactors or PunchSpringFactors
            The springs' factors (:mod:`mdr_events.theory.layer.spring_factors`).
        """
        return cls._spring_type()(indenter, params.E_star, params.G_star, params.nu, layer)

    @staticmethod
    def _spring_type() -> type:
        from mdr_events.theory.layer.spring_factors import SpringFactors

        return SpringFactors

    @staticmethod
    def force_reader(params: Parameters, indenter, layer: Layer) -> Callable[[Any, Any], np.ndarray]:
        """``F_N(d, a) = F₀(a) + K(a)(d − g(a))`` (generalised (10), :func:`~mdr_events.theory.layer.normal_force`),
        its table and ``κₙ c`` read once.

        Parameters
        ----------
        params : Parameters
            The material.
        indenter : Paraboloid or PowerLaw
            The indenter.
        layer : Layer
            The layer.

        Returns
        -------
        callable
            ``F_N`` (N) of the depth and radius ``d``, ``a`` (float or array_like, m).
        """
        from mdr_events.theory.layer.compliance import LAMBDA_MAX
        from mdr_events.theory.layer.relations import _abel_factor, _force_of_factors, _power_law
        from mdr_events.theory.layer.tables import LAMBDA_MIN, layer_table

        c, exponent = _power_law(indenter)
        table, kc = layer_table(params.nu, layer.base, exponent), _abel_factor(exponent) * c

        def force(depth, radius) -> np.ndarray:
            # (the relation unchecked, its table and κₙc kept: the continuum hands it valid radii and depths, and the
            # arguments' checks and look-ups cost half the call; within the splines their values alone)
            a = np.asarray(radius, dtype=float)
            lam = np.abs(a) / layer.thickness
            inside = lam.size > 0 and LAMBDA_MIN <= float(np.min(lam)) and float(np.max(lam)) <= LAMBDA_MAX
            with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):  # (as the checked one)
                factors = table.spline_force_factors(lam) if inside else table.force_factors(lam)
                return _force_of_factors(depth, a, kc, exponent, params.E_star, factors)

        return force


class PunchNormal(ProfileNormal):
    """The flat punch on a layer: ``g = 0`` under the face, :class:`~.layer_punch_branch.LayerPunchBranch`,
    ``F_N = K(a) d``."""

    @staticmethod
    def exponent(indenter) -> float:
        """2: the normal table of the paraboloid's exponent, whose ``Θ`` and ``Φ`` the punch reads (its profile
        factor unread, ``g = 0``).

        Parameters
        ----------
        indenter : FlatPunch
            The punch.

        Returns
        -------
        float
            2.
        """
        return 2.0

    @staticmethod
    def branch(params: Parameters, work: float, indenter, layer: Layer, factors):
        """The face held, then receding (:class:`~.layer_punch_branch.LayerPunchBranch`).

        Parameters
        ----------
        params : Parameters
            The material.
        work : float
            The work of adhesion (J/m²).
        indenter : FlatPunch
            The punch.
        layer : Layer
            The layer.
        factors : NormalFactors
            The layer's normal factors.

        Returns
        -------
        LayerPunchBranch
            The branch.
        """
        from .layer_punch_branch import LayerPunchBranch

        return LayerPunchBranch(params, work, indenter, layer, factors)

    @staticmethod
    def _spring_type() -> type:
        from mdr_events.theory.layer.spring_factors import PunchSpringFactors

        return PunchSpringFactors

    @staticmethod
    def force_reader(params: Parameters, indenter, layer: Layer) -> Callable[[Any, Any], np.ndarray]:
        """``F_N(d, a) = K(a) d`` (``layer_flat_punch_force``; the springs let go store nothing,
        ``layer_flat_punch_receding_force``), ``K = 2E* a Φ(a/h)`` the layer's punch stiffness at the contact's
        radius: ``Φ`` read off the table's spline as a piecewise polynomial on the arrays
        (:meth:`~mdr_events.theory.layer.scalar_factors.LogColumn.values_array`, the spline's values to round-off) where
        every radius lies within the spline's ``[LAMBDA_MIN, LAMBDA_MAX] h``, else the checked relation
        (:meth:`checked_force_reader`).

        Parameters
        ----------
        params : Parameters
            The material.
        indenter : FlatPunch
            The punch.
        layer : Layer
            The layer.

        Returns
        -------
        callable
            ``F_N`` (N; 0 where ``a = 0``) of the depth and radius ``d``, ``a`` (float or array_like, m).
        """
        from mdr_events.theory.layer.compliance import LAMBDA_MAX
        from mdr_events.theory.layer.scalar_factors import LogColumn
        from mdr_events.theory.layer.tables import LAMBDA_MIN, layer_table
        from mdr_events.theory.layer_symbolic import derive_layer_model

        relation = derive_layer_model()["layer_flat_punch_force"].numeric
        column = LogColumn(layer_table(params.nu, layer.base, 2.0)._splines["stiffness"])
        checked = PunchNormal.checked_force_reader(params, indenter, layer)

        face = np.array([float(indenter.radius)])
        held = column.values_array(face / layer.thickness)[0] if LAMBDA_MIN <= face[0] / layer.thickness <= LAMBDA_MAX \
            else None

        def force(depth, radius) -> np.ndarray:
            a = np.asarray(radius, dtype=float)
            lam = a / layer.thickness
            if not (lam.size > 0 and LAMBDA_MIN <= float(np.min(lam)) and float(np.max(lam)) <= LAMBDA_MAX):
                return checked(depth, radius)  # (a = 0, below the series' bound or beyond the table: checked)
            # (the face's radius, most of a run's samples: its Φ read once, the same value elementwise)
            at_face = a == face[0]
            if held is None or not np.any(at_face):
                factor = column.values_array(lam)
            else:
                factor = np.full(a.shape, held)
                factor[~at_face] = column.values_array(lam[~at_face])
            return np.asarray(relation(2.0 * params.E_star * a * factor, depth), dtype=float)

        return force

    @staticmethod
    def checked_force_reader(params: Parameters, indenter, layer: Layer) -> Callable[[Any, Any], np.ndarray]:
        """:meth:`force_reader`'s ``F_N = K(a) d`` by the checked relation
        :func:`~mdr_events.theory.layer.punch_stiffness` (the B-spline, the series below ``LAMBDA_MIN``): what it
        reads outside the spline, and what its piecewise polynomial is tested against. Its parameters and what it
        returns are :meth:`force_reader`'s.
        """
        from mdr_events.theory.layer import punch_stiffness
        from mdr_events.theory.layer_symbolic import derive_layer_model

        relation = derive_layer_model()["layer_flat_punch_force"].numeric

        def force(depth, radius) -> np.ndarray:
            radius = np.asarray(radius, dtype=float)
            with np.errstate(invalid="ignore"):
                stiffness = punch_stiffness.__wrapped__(np.where(radius > 0, radius, 0.0), params.E_star, params.nu,
                                                        layer)
            return np.asarray(relation(stiffness, depth), dtype=float)

        return force


#: The normal springs of each kind of indenter on a layer, by its type.
LAYER_NORMALS: dict[type, type[ProfileNormal]] = {Paraboloid: ProfileNormal, PowerLaw: ProfileNormal,
                                                  FlatPunch: PunchNormal}
