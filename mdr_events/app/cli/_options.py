"""The options several verbs share, and how their values become the package's values (:mod:`mdr_events.app.inputs`).

Each ``*_options`` function adds options to a verb's parser; the function of the same input's name reads them from
argparse's namespace through the shared parser and names the option in a :class:`UsageError` where it fails.

This module imports only the standard library when imported: ``mdr-events --help`` lists the verbs without loading
the package, and a verb's options are added (and what they need imported) when the verb is used
(:meth:`Parser.filled`).
"""

from __future__ import annotations

import argparse
import math
import os
import re
from typing import TYPE_CHECKING, Callable, Sequence

if TYPE_CHECKING:
    from mdr_events.contact import Contact
    from mdr_events.contact.friction import FrictionLaw
    from mdr_events.limits import Limits
    from mdr_events.models.indenters import SimulatedProfile
    from mdr_events.models.motion import Motion
    from mdr_events.parameters import Parameters


class UsageError(Exception):
    """A user error: reported in one line, exit status 2."""


#: The namespace's record of the options given so far (option's destination -> its value), for :class:`StoreOnce`.
GIVEN = "_options_given"


class StoreOnce(argparse._StoreAction):
    """Store an option's value, refusing the option given twice (the last one silently won): every verb's options
    that take a value (:class:`Parser` makes it their action)."""

    def __call__(self, parser, namespace, values, option_string=None) -> None:
        given = getattr(namespace, GIVEN, None)
        if given is None:
            given = {}
            setattr(namespace, GIVEN, given)
        if self.dest in given:
            several = f", with every value after it ({option_string} {' '.join(map(str, given[self.dest] + values))})" \
                if isinstance(values, list) else ""
            raise argparse.ArgumentError(self, f"given twice ({given[self.dest]!r} and {values!r}); allowed: "
                                               f"once{several}")
        given[self.dest] = values
        setattr(namespace, self.dest, values)


def _typed(kind: type) -> Callable[[str], float | int]:
    """The argparse type of ``float`` or ``int`` (:func:`~mdr_events.validation.plain_number`, imported when a value
    is read): its error the option's one line (``argument --alpha: '1_0' is not allowed; allowed: ...``)."""

    def typed(text: str) -> float | int:
        from mdr_events.validation import plain_number

        try:
            return plain_number(text, kind)
        except ValueError as error:
            raise argparse.ArgumentTypeError(str(error)) from None

    typed.__name__ = kind.__name__
    return typed


#: An argument that is a negative number (with an exponent, ``inf`` or ``nan`` too), read as a value.
NEGATIVE_NUMBER = re.compile(r"^-(?:(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|inf|infinity|nan)$", re.IGNORECASE)

#: argparse's error for an option whose value is missing (or was a word that begins with "-").
MISSING_VALUE = re.compile(r"^argument (\S+): expected (?:one argument|at least one argument|\d+ arguments?)$")
#: argparse's error for a value (or a verb: the argument ``command``) that is not among the choices.
INVALID_CHOICE = re.compile(r"^argument (\S+): invalid choice: (.*) \(choose from (.*)\)$")


def _choice_message(argument: str, value: str, choices: str) -> str:
    """The one line of a value that is not among an argument's choices, in the package's words: the verb, or the
    option, with the value and the allowed ones (argparse's own: "argument command: invalid choice: ...")."""
    allowed = ", ".join(choice.strip().strip("'") for choice in choices.split(","))
    value = _cut(value)  # (argparse's repr of the value, whole: 100 kB for a value of 100 000 characters)
    if argument == "command":
        return f"the verb {value} is not allowed; allowed: {allowed} (mdr-events --help says what each does)"
    return f"argument {argument}: invalid choice: {value}; allowed: {allowed}"


#: Characters of a value a usage error shows: ``validation.SHOWN_CHARACTERS``, written here, not imported (a usage
#: error of a short value loads no numpy; tests/test_hostile_round_twenty_nine_io.py checks that the two agree).
CUT_CHARACTERS = 80


def _cut(text: str, count: int = 1) -> str:
    """``text`` (a value as argparse shows it, or the words it did not take) cut to :data:`CUT_CHARACTERS`
    (:func:`~mdr_events.validation.cut_text`, imported only to cut), with the count of the words when there are
    several (a shell's glob of ten thousand files: 300 kB on one line)."""
    if len(text) <= CUT_CHARACTERS:
        return text
    from mdr_events.validation import cut_text

    return cut_text(text, CUT_CHARACTERS) + (f" ({count} words)" if count > 1 else "")


class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line (:class:`UsageError`) naming where the allowed options are, and
    whose options of a value are given once (:class:`StoreOnce`). A number's option (``type=float`` or ``int``)
    reads plain decimal notation only (:func:`~mdr_events.validation.plain_number`): not ``1_0`` nor ``２０``,
    which Python's ``float()`` reads.

    ``fill``, a function of the parser, adds its arguments when they are first needed (to parse, to show the help, to
    list them: :meth:`filled`), so that a verb's imports are made only when the verb is used.
    """

    def __init__(self, *args, fill: Callable[[Parser], None] | None = None, **kwargs) -> None:
        # no abbreviations: ``lammps-check ... --h 1e-3`` (the layer's option of other verbs) was read as --help,
        # printed it and exited 0 with nothing checked (round eighteen)
        super().__init__(*args, **dict(kwargs, allow_abbrev=False))
        # a negative number is a value, not an option, in every notation a value is read in: argparse's own rule
        # (``-2``, ``-.5``) took ``--E -1e5`` or ``--tau0 -inf`` for a missing value ("expected one argument")
        self._negative_number_matcher = NEGATIVE_NUMBER
        self.register("action", None, StoreOnce)
        self.register("action", "store", StoreOnce)
        self.register("type", float, _typed(float))
        self.register("type", int, _typed(int))
        self._fill = fill

    def filled(self) -> Parser:
        """This parser with its arguments added (``fill`` called once)."""
        fill, self._fill = self._fill, None
        if fill is not None:
            fill(self)
        return self

    def parse_known_args(self, args=None, namespace=None):  # (argparse parses a verb's arguments through this)
        return super(Parser, self.filled()).parse_known_args(args, namespace)

    def format_help(self) -> str:
        return super(Parser, self.filled()).format_help()

    def format_usage(self) -> str:
        return super(Parser, self.filled()).format_usage()

    def error(self, message: str) -> None:  # one line, no usage block
        invalid = INVALID_CHOICE.match(message)
        if invalid:
            raise UsageError(_choice_message(*invalid.groups()))
        missing = MISSING_VALUE.match(message)
        if missing:  # (argparse reads a word that begins with "-" as an option, never as the value)
            option = missing.group(1).split("/")[0]
            message += f"; allowed: {option} VALUE (a value that begins with '-' written as {option}=VALUE)"
        raise UsageError(message)

    def parse_args(self, args=None, namespace=None):  # unknown options named with where to find the allowed
        parsed, extras = self.parse_known_args(args, namespace)
        if extras:
            command = getattr(parsed, "command", None)
            where = f"{self.prog} {command}" if command else self.prog
            raise UsageError(f"unrecognized argument(s) {_cut(' '.join(extras), len(extras))}; allowed: the options "
                             "listed by "
                             f"{where} --help")
        return parsed


def shown_number(value: float) -> str:
    """A number as a message echoes the option's value: ``:g``'s short form where it reads back as the same float,
    else ``repr``'s every digit (round nineteen: ``--rate-exponent 1.0000001`` was echoed ``--rate-exponent 1``, a
    value the message's own "0 < N <= 1" allows)."""
    short = f"{value:g}"
    return short if value != value or float(short) == value else repr(float(value))


def output_directory(args: argparse.Namespace):
    """``--out``, prepared (a directory that exists or can be created, writable), before anything is computed."""
    from mdr_events.io.files import prepare_output_directory

    return prepare_output_directory(args.out, "--out")


# --- parameters -------------------------------------------------------------------------------------------------
def value_options(parser: argparse.ArgumentParser) -> None:
    """``--E``, ``--nu``, ...: one option per parameter, in SI units."""
    from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS

    for name, long_name in PARAMETER_LONG_NAMES.items():
        parser.add_argument(f"--{name}", type=float, default=None, metavar="VALUE",
                            help=f"{long_name} [{PARAMETER_UNITS[name]}]")


def parameter_options(parser: argparse.ArgumentParser) -> None:
    """``--preset`` and the parameters' values (``phase-diagram``, ``simulate``)."""
    from mdr_events.app import inputs
    from mdr_events.parameters import PRESETS

    parser.add_argument("--preset", choices=sorted(PRESETS), default=inputs.DEFAULT_PRESET,
                        help="parameter set of the paper (default paper-R30); the options below override it")
    value_options(parser)


def _changes(args: argparse.Namespace) -> dict[str, float]:
    from mdr_events.parameters import PARAMETER_UNITS

    return {name: getattr(args, name) for name in PARAMETER_UNITS if getattr(args, name) is not None}


def parameters(args: argparse.Namespace) -> tuple[Parameters, dict[str, str]]:
    """The parameters of ``--preset`` with the options given, and attributes saying which came from the preset."""
    from mdr_events.app import inputs

    return inputs.parameters(args.preset, _changes(args))


def measured_parameters(args: argparse.Namespace) -> tuple[Parameters, dict[str, str]]:
    """The parameters of ``validate`` and ``fit``: ``--params FILE`` or ``--preset``, with the options given."""
    from mdr_events.app import inputs
    from mdr_events.app.study import load_parameters_file

    if args.params is not None:
        try:
            return load_parameters_file(args.params, _changes(args))
        except ValueError as error:
            raise UsageError(f"--params {error}") from None
    try:
        return inputs.parameters(args.preset, _changes(args))
    except ValueError as error:
        raise UsageError(str(error)) from None


# --- the indenter, the friction law, the limits -----------------------------------------------------------------
def profile_options(parser: argparse.ArgumentParser) -> None:
    """``--power-law C N``, ``--flat-punch RADIUS`` or ``--table FILE``."""
    indenter = parser.add_mutually_exclusive_group()
    indenter.add_argument("--power-law", type=float, nargs=2, default=None, metavar=("C", "N"),
                          help="the indenter f = c r^n (c in m^(1-n), n >= 1: 1 a cone) instead of the paraboloid of R")
    indenter.add_argument("--flat-punch", type=float, default=None, metavar="RADIUS",
                          help="the flat punch of this radius (m) instead of the paraboloid of R")
    indenter.add_argument("--table", default=None, metavar="FILE",
                          help="a tabulated indenter: a CSV file with the columns r and f (m) instead of the paraboloid")


def profile(args: argparse.Namespace, simulated: bool = True) -> SimulatedProfile:
    """The indenter of :func:`profile_options` (``None``: the paraboloid of the parameters' ``R``); ``simulated``: one
    the simulators take, else any the closed forms take (the phase diagram's)."""
    from mdr_events.app import inputs
    from mdr_events.validation import shown_path

    if args.table is not None:
        given = f"--table {shown_path(args.table)}"
    elif args.flat_punch is not None:
        given = f"--flat-punch {shown_number(args.flat_punch)}"
    elif args.power_law is not None:
        given = f"--power-law {' '.join(f'{shown_number(value)}' for value in args.power_law)}"
    else:
        return None
    try:
        return inputs.indenter(args.power_law, args.flat_punch, args.table, simulated)
    except (TypeError, ValueError) as error:
        raise UsageError(f"{given}: {error}") from None


def friction_options(parser: argparse.ArgumentParser) -> None:
    """``--friction LAW`` and ``--mu MU``."""
    from mdr_events.contact.friction import FRICTION_LAWS

    parser.add_argument("--friction", choices=list(FRICTION_LAWS), default=None,
                        help="the cap on the springs' shifts: tau0 (the paper's, default), coulomb (mu times the "
                             "spring's normal force) or tau0+coulomb (their sum)")
    parser.add_argument("--mu", type=float, default=None, help="the coefficient of friction of --friction coulomb "
                        "or tau0+coulomb")


def friction(args: argparse.Namespace) -> FrictionLaw:
    """The ``--friction LAW [--mu MU]`` law (default the paper's ``tau0``)."""
    from mdr_events.app import inputs

    try:
        return inputs.friction(args.friction, args.mu)
    except (TypeError, ValueError) as error:
        law = f"--friction {args.friction}" if args.friction else "the default --friction tau0"
        given = law if args.mu is None else (f"--mu {shown_number(args.mu)} with {law}" if not args.friction
                                             else f"{law} --mu {shown_number(args.mu)}")
        raise UsageError(f"{given}: {error}") from None


def adhesion_options(parser: argparse.ArgumentParser) -> None:
    """``--adhesion-law LAW``, ``--v-ref V_REF`` and ``--rate-exponent N``: the rate-dependent adhesion law."""
    from mdr_events.app import inputs

    parser.add_argument("--adhesion-law", choices=list(inputs.ADHESION_LAWS), default=None,
                        help="the works of adhesion of Hess's rule: paper (dgamma0 in, dgamma1 out, rate independent; "
                             "default) or rate (Maugis-Barquins: dgamma1 [1 + (s/v_ref)^n] receding, dgamma0 / "
                             "[1 + (s/v_ref)^n] advancing, s the edge's speed; needs --v-ref and --rate-exponent)")
    parser.add_argument("--v-ref", type=float, default=None, metavar="V_REF",
                        help="the rate law's reference speed of the contact's edge in m/s (> 0)")
    parser.add_argument("--rate-exponent", type=float, default=None, metavar="N",
                        help="the rate law's exponent n of the edge's speed (0 < n <= 1)")


def adhesion(args: argparse.Namespace, params: Parameters):
    """The adhesion law of :func:`adhesion_options` with the works at rest of ``params`` (a verb without the options:
    the paper's law of ``params``)."""
    from mdr_events.app import inputs

    law, v_ref, n = (getattr(args, name, None) for name in ("adhesion_law", "v_ref", "rate_exponent"))
    given = {"--v-ref": v_ref, "--rate-exponent": n}
    if law != "rate":  # (the options' names in the one line; the values' own checks are the law's)
        for option, value in given.items():
            if value is not None:
                raise UsageError(f"{option} {shown_number(value)} is not allowed with the adhesion law "
                                 f"{law or 'paper'!r}; allowed: "
                                 "--v-ref and --rate-exponent with --adhesion-law rate")
    else:
        missing = [option for option, value in given.items() if value is None]
        if missing:
            raise UsageError(f"--adhesion-law rate lacks {' and '.join(missing)}; allowed: --adhesion-law rate with "
                             "both --v-ref V_REF (m/s, > 0) and --rate-exponent N (0 < N <= 1)")
    try:
        return inputs.adhesion(law, params, v_ref, n)
    except (TypeError, ValueError) as error:
        shown_ = " ".join(f"{option} {shown_number(value)}" for option, value in given.items() if value is not None)
        raise UsageError(f"--adhesion-law rate {shown_}: {error}") from None


def is_rate_law(contact: Contact) -> bool:
    """Whether ``contact``'s adhesion law is the rate-dependent one (``--adhesion-law rate``)."""
    return contact.adhesion.is_rate_dependent


def check_rate_run(contact: Contact, motion, method, verb: str) -> None:
    """Refuse, before anything is written, the rate law (``--adhesion-law rate``) where ``verb``'s method does not run
    it with the other options (:func:`~mdr_events.app.inputs.check_rate_run`): one line naming the option."""
    from mdr_events.app import inputs

    try:
        inputs.check_rate_run(contact, motion, method, verb)
    except (TypeError, ValueError) as error:
        raise UsageError(f"--adhesion-law rate with --method {method.name}: {error}") from None


def layer_options(parser: argparse.ArgumentParser) -> None:
    """``--h H`` and ``--layer-base BASE``: the elastomer as a layer of thickness ``H`` on a rigid base."""
    from mdr_events.contact.layer import LayerBase

    parser.add_argument("--h", type=float, default=None, metavar="H",
                        help="the elastomer's thickness in m, a layer on a rigid base (default inf: the half-space; "
                             "simulate and sweep run every friction law there, validate and fit the friction "
                             "law tau0)")
    parser.add_argument("--layer-base", choices=[base.value for base in LayerBase], default=None,
                        help="how the layer rests on its base (default bonded; frictionless: no tangential motion)")


def check_base_has_layer(base: str | None, thickness: float, given: str) -> None:
    """Refuse ``--layer-base`` on the half-space (``thickness`` inf, as ``given``): it rests on no base, and the
    option was ignored in silence (round 29), as ``--mu`` without Coulomb's law or ``--v-ref`` without the rate law
    are refused."""
    if base is not None and thickness == math.inf:
        raise UsageError(f"--layer-base {base} {given} is not allowed: the half-space rests on no base; allowed: "
                         "--layer-base with --h H, a layer's finite thickness in m")


def layer(args: argparse.Namespace, over_study: bool = False):
    """The layer of ``--h`` and ``--layer-base`` (the half-space without them; a verb without the options: the
    half-space); ``--layer-base`` on the half-space is refused (:func:`check_base_has_layer`) unless ``over_study``
    (a sweep's, whose study's [layer] or grid over h may hold the layer)."""
    from mdr_events.app import inputs

    h, base = getattr(args, "h", None), getattr(args, "layer_base", None)
    if not over_study:  # (a sweep's --layer-base sets the base of its study's [layer], or of a grid over h)
        check_base_has_layer(base, math.inf if h is None else h, "without --h" if h is None else "with --h inf")
    try:
        return inputs.layer(h, base)
    except (TypeError, ValueError) as error:
        given = " ".join(part for part in (f"--h {shown_number(h)}" if h is not None else "",
                                           f"--layer-base {base}" if base is not None else "") if part)
        raise UsageError(f"{given}: {error}") from None


def check_reference_layer(contact: Contact, motion, verb: str) -> None:
    """Refuse, before anything is read, a layer the continuum reference of ``verb`` does not take (``--friction``
    other than tau0 with ``--h``; a frictionless base on a path with tangential motion): one line.

    Parameters
    ----------
    contact : Contact
        The contact of the options.
    motion : Scenario or Paths
        The measured path.
    verb : str
        ``"validate"`` or ``"fit"``.

    Raises
    ------
    UsageError
        What the continuum does not take on the layer, naming the options.
    """
    from mdr_events.models.methods import Continuum
    from mdr_events.models.simulate import check_layer_taken

    try:
        check_layer_taken(contact, motion, Continuum(), where=verb)
    except (TypeError, ValueError) as error:
        raise UsageError(f"--h {shown_number(contact.layer.thickness)}: {error}") from None


def contact(args: argparse.Namespace, params: Parameters, simulated: bool = True) -> Contact:
    """The contact of ``params`` with the indenter, the friction law, the layer and the adhesion law of the options."""
    from mdr_events.app import inputs

    return inputs.contact(params, profile(args, simulated), friction(args), layer(args), adhesion(args, params))


def limit_options(parser: argparse.ArgumentParser) -> None:
    """``--limit NAME=VALUE`` (repeatable): raise a resource limit of :class:`~mdr_events.limits.Limits`."""
    from mdr_events.limits import LIMIT_UNITS

    parser.add_argument("--limit", action="append", default=[], metavar="NAME=VALUE",
                        help="raise a resource limit, e.g. --limit steps=1e8 --limit memory=8GiB (names: "
                             + ", ".join(f"{name}: {meaning}" for name, meaning in LIMIT_UNITS.items())
                             + "; inf: none)")


def limits(args: argparse.Namespace) -> Limits:
    """The limits of ``--limit`` options, on top of the defaults."""
    from mdr_events.app import inputs

    return inputs.limits(args.limit)


# --- measured runs: validate and fit -------------------------------------------------------------------------------
def measured_path_options(parser: argparse.ArgumentParser, what: str, start: bool = False) -> None:
    """The parameters (preset, file or values) and the path (scenario and angle, or a path file) of measured
    runs: ``validate`` and ``fit``."""
    from mdr_events.models.motion import SCENARIO_NAMES
    from mdr_events.parameters import PRESETS

    role = "the start of the fit" if start else "the parameters"
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--preset", choices=sorted(PRESETS), default=None,
                        help=f"{role}: a parameter set of the paper (default paper-R30); the options below override it")
    source.add_argument("--params", default=None, metavar="FILE",
                        help=f"{role}: a TOML file with a [parameters] table as in a study file (e.g. the study file)")
    value_options(parser)
    motion = parser.add_mutually_exclusive_group(required=True)
    motion.add_argument("--scenario", choices=list(SCENARIO_NAMES), help=f"the scenario the {what} took (with --alpha)")
    motion.add_argument("--path", default=None, metavar="FILE",
                        help="a TOML file with a [path] table as in a study file: waypoints = [[x, d], ...] (m), "
                             "speed (m/s, default the parameters' v)")
    parser.add_argument("--alpha", type=float, default=None, metavar="DEG",
                        help="the scenario's angle in degrees")


def measured_motion(args: argparse.Namespace, params: Parameters, contact: Contact) -> tuple[Motion, str]:
    """The one path the runs took (:func:`measured_path_options`) as a motion, and a description of it."""
    from mdr_events.app import inputs
    from mdr_events.app.study import load_path_file

    if args.path is not None:
        if args.alpha is not None:
            raise UsageError(f"--alpha {shown_number(args.alpha)} is not allowed with --path (its waypoints fix the "
                             "motion)")
        try:
            return inputs.paths(load_path_file(args.path, params), params), f"from the path file {args.path}"
        except ValueError as error:
            raise UsageError(f"--path {error}") from None
    if args.alpha is None:
        raise UsageError(f"--scenario {args.scenario} needs --alpha (one angle in degrees)")
    try:
        motion = inputs.scenario(args.scenario, [args.alpha], params)
        motion.cases(params, contact.profile)  # (an angle whose path cannot be run is named with --alpha)
    except (ValueError, TypeError) as error:
        raise UsageError(f"--alpha {shown_number(args.alpha)}: {error}") from None
    return motion, f"scenario {args.scenario}, α = {shown_number(args.alpha)}°"


def check_not_overwritten(args: argparse.Namespace, out, stem: str, suffixes: Sequence[str], inputs_: Sequence[str],
                          what: str) -> None:
    """Refuse an ``--out`` where writing ``<stem><suffix>`` would overwrite one of the input files."""
    given = {os.path.realpath(name) for name in inputs_}
    clash = [target for target in (out / f"{stem}{suffix}" for suffix in suffixes) if os.path.realpath(target) in given]
    if clash:
        raise UsageError(f"--out {args.out}: writing {what.replace('{target}', str(clash[0]))}; allowed: another "
                         "directory")
