"""Command line: ``mdr-events derive | phase-diagram | simulate | validate | fit | sweep | run | reproduce |
lammps-check``.

Every error prints one line ``mdr-events: error: ...`` on stderr (no traceback; ``mdr-events --debug ...``
re-raises it with its traceback). The exit status (:data:`EXIT_STATUSES`):

- 0: done;
- 1: ``mdr-events validate`` (or ``run`` with a ``[validate]`` table) or ``lammps-check``: a run is outside its
  tolerance;
  ``mdr-events fit`` (or ``run`` with a ``[fit]`` table): a free parameter is not determined by the data;
- 2: bad input: an argument, a value, a study file or a file that cannot be read or written (``ValueError``,
  ``TypeError``, ``KeyError``, ``OSError``), named with its value and what is allowed. Output directories
  are checked before anything is computed (:func:`~mdr_events.io.files.prepare_output_directory`);
- 3: the computation failed although the input was accepted: the solver gave up (``RuntimeError``), memory
  or another resource ran out (``MemoryError``), or an internal error (any other exception): please report it;
- 130 / 143: interrupted by Ctrl-C (SIGINT) / terminated (SIGTERM). Both remove the temporary file being
  written (:func:`~mdr_events.io.files.atomic_write`): no file is left half-written.

One module per verb (:data:`VERBS`): each adds its parser (``add_arguments(subparsers)``) and turns argparse's
namespace into a typed job of :mod:`mdr_events.app.jobs` (``job(args)``), the job a study file's table gives for the
same input; ``run(args)`` runs it and prints what it wrote. The options several verbs share, and how they are read
through the shared parsers (:mod:`mdr_events.app.inputs`), are in :mod:`mdr_events.app.cli._options`.

Importing this module imports the standard library only: ``mdr-events --help`` lists the verbs without loading the
package, a verb's options are added (and what they need imported) when the verb is used
(:meth:`~mdr_events.app.cli._options.Parser.filled`), and everything else is imported inside :func:`main`, where a
Ctrl-C (even during the imports) prints one line and exits with 130. The console script's entry point,
:func:`mdr_events.app.console.console_main`, does the same while this module is imported.
"""

from __future__ import annotations

import _thread
import argparse
import functools
import math
import os
import re
import signal
import sys
import threading
import time
from typing import Sequence

from mdr_events._version import __version__
from mdr_events.app.cli import derive, fit, lammps_check, phase_diagram, reproduce, run, simulate, sweep, validate
from mdr_events.app.cli._options import Parser, UsageError, _cut
from mdr_events.app.cli._stdout import stdout_named
from mdr_events.app.console import INTERRUPTED_LINES

__all__ = ["main", "console_main", "build_parser", "UsageError", "EXIT_STATUSES", "VERBS"]

#: The verbs in the order ``--help`` lists them: each module's ``add_arguments`` adds its parser.
VERBS = (derive, phase_diagram, simulate, validate, fit, sweep, run, reproduce, lammps_check)

#: The first line of ``mdr-events --help`` (plain text: argparse prints it as it is).
DESCRIPTION = ("Adhesive indentation and detachment at an angle with the Method of Dimensionality Reduction "
               "(Lyashenko, Popov & Borysiuk 2023, section 4).")


#: Exit status -> when.
EXIT_STATUSES = {
    0: "done",
    1: "validate, lammps-check: a run is outside its tolerance; fit: a free parameter is not determined or the fit does not "
       "describe the data",
    2: "bad input (an argument, a value, a study file, a file that cannot be read or written)",
    3: "the computation failed although the input was accepted (solver, memory, internal error)",
    130: "interrupted (Ctrl-C)",
    141: "the reader of the output went away (a closed pipe: `mdr-events derive | head`), silently",
    143: "terminated (SIGTERM)",
}
#: The exit status when the output's reader has gone: as a process ended by SIGPIPE (128 + 13).
EXIT_BROKEN_PIPE = 141
#: The exit status of bad input and of a failed computation.
EXIT_BAD_INPUT, EXIT_FAILED = 2, 3
#: Errors that are bad input (exit 2); RuntimeError and MemoryError are a failed computation (exit 3).
INPUT_ERRORS = (ValueError, TypeError, KeyError, OSError)
COMPUTATION_ERRORS = (RuntimeError, MemoryError)


class _Terminated(BaseException):
    """SIGTERM arrived: raised in the main thread, so that every ``finally`` (temporary files) runs."""


class _SwallowedInterrupts:
    """Ctrl-C (or SIGTERM) that the interpreter swallowed, raised again where :func:`main` handles it.

    An interrupt that lands while the garbage collector runs Python code (a weak reference's callback, a ``__del__``)
    is "Exception ignored in ...": printed with its traceback, and the command goes on to exit 0. While :func:`main`
    runs, ``sys.unraisablehook`` notes such an interrupt (printing nothing) and has a helper thread interrupt the main
    thread again (``_thread.interrupt_main``), where its own code runs: raised inside the hook, it would be swallowed
    again. :meth:`settle` waits until every such interrupt has arrived (catching it), so that none arrives after
    :func:`main` has returned; one noted when the command has done its work ends it as if it had arrived then.
    """

    def __init__(self) -> None:
        self.interrupts: list[BaseException] = []
        self.pending: list[list[bool]] = []  # one per interrupt raised again: [True] once it has been
        self.previous = sys.unraisablehook
        self.ignored_sigint: object = None  # SIGINT's handler of before, where a Python one was put in its place

    def __enter__(self) -> _SwallowedInterrupts:
        self.previous = sys.unraisablehook
        sys.unraisablehook = self.hook
        return self

    def __exit__(self, *exc_info) -> None:
        sys.unraisablehook = self.previous
        if self.ignored_sigint is not None:
            signal.signal(signal.SIGINT, self.ignored_sigint)
            self.ignored_sigint = None

    def _let_sigint_through(self) -> None:
        """A simulated Ctrl-C reaches the main thread through a Python handler of SIGINT alone
        (``_thread.interrupt_main`` does nothing where SIGINT is ignored, as in a background job, which would let a
        swallowed SIGTERM's command run on and write its files): where SIGINT has none, Python's own is put in place
        until :meth:`__exit__` (the command is ending: a real Ctrl-C now ends it as the noted interrupt does)."""
        if self.ignored_sigint is None and not callable(signal.getsignal(signal.SIGINT)):
            previous = signal.signal(signal.SIGINT, signal.default_int_handler)
            self.ignored_sigint = signal.SIG_DFL if previous is None else previous  # (None: not set from Python)

    def hook(self, unraisable) -> None:
        """``sys.unraisablehook``: an interrupt is noted and raised again; anything else goes to the previous hook."""
        kind = unraisable.exc_type
        if not (isinstance(kind, type) and issubclass(kind, (KeyboardInterrupt, _Terminated))
                and threading.current_thread() is threading.main_thread()):
            self.previous(unraisable)
            return
        self.interrupts.append(unraisable.exc_value if unraisable.exc_value is not None else kind())
        self._let_sigint_through()
        while True:
            try:
                done: list[bool] = []
                self.pending.append(done)
                _thread.start_new_thread(_interrupt_main, (done,))  # (threading.Thread.start waits: not here)
                return
            except KeyboardInterrupt:  # it arrived here, inside the hook, where it would be swallowed: once more
                continue

    def settle(self) -> None:
        """Wait until the interrupts raised again have arrived; catch them (:attr:`interrupts` has them)."""
        while self.pending:
            try:
                while not self.pending[0]:
                    time.sleep(0.001)
                _checkpoint()
            except KeyboardInterrupt:
                continue
            self.pending.pop(0)


def _interrupt_main(done: list[bool]) -> None:
    """In a helper thread: Ctrl-C (simulated) for the main thread; ``done`` gets True."""
    try:
        _thread.interrupt_main(signal.SIGINT)
    finally:
        done.append(True)


def _checkpoint() -> None:
    """A Python call: a pending signal's handler runs on entering it."""


def progress(message: str) -> None:
    """A progress line, on stderr (stdout holds the files written and the summaries); nowhere if there is no stderr
    (``2>&-``: ``print`` would write it to stdout, among the files written)."""
    if sys.stderr is not None:
        print(message, file=sys.stderr, flush=True)


def build_parser() -> argparse.ArgumentParser:
    """The parser of ``mdr-events``: one sub-parser per verb (:data:`VERBS`), each setting ``run``."""
    parser = Parser(prog="mdr-events", description=DESCRIPTION, epilog="exit status: " + "; ".join(
        f"{status} {meaning}" for status, meaning in EXIT_STATUSES.items()))
    parser.add_argument("--version", action="version", version=f"mdr_events {__version__}")
    parser.add_argument("--debug", action="store_true",
                        help="on an error, show the traceback (re-raise it) instead of one line")
    # not required here: a missing command is reported by main(), after unknown options are named
    commands = parser.add_subparsers(dest="command", parser_class=Parser)
    for verb in VERBS:
        verb.add_arguments(commands)
    names = ", ".join(commands.choices)

    def missing_command(args: argparse.Namespace) -> None:  # a command's own default replaces this one
        raise UsageError(f"a command is required; allowed: {names}")

    parser.set_defaults(run=missing_command)
    return parser


def _one_line(message: str) -> str:
    """A message on one line: its lines joined (nothing is cut), and any other control character written as ``repr``
    writes it (a file's name or a header's cell holding ``ESC[31m`` or a bell reached the terminal raw)."""
    line = " ".join(part.strip() for part in message.splitlines() if part.strip())
    if line.isprintable():
        return line
    from mdr_events.validation import shown_text  # (here: derive's errors need no numpy)

    return shown_text(line, math.inf)


def _message(error: BaseException) -> str:
    """What an error says, for ``mdr-events: error: ...``."""
    if isinstance(error, KeyError) and error.args:
        return str(error.args[0])
    if isinstance(error, OSError) and error.filename is not None:
        files = " -> ".join(os.fsdecode(name) for name in (error.filename, error.filename2) if name is not None)
        return f"{files}: {error.strerror or error}"
    return str(error)


def _on_sigterm(arrived: list[int], signum: int, frame) -> None:
    arrived.append(signum)
    signal.signal(signum, signal.SIG_IGN)  # a second SIGTERM must not interrupt the clean-up
    raise _Terminated(signum)


def _on_sigint(arrived: list[int], signum: int, frame) -> None:
    """Python's own handler of Ctrl-C (``KeyboardInterrupt``), which notes first that it arrived: code that catches
    what it raises (numpy's import turns it into an ``ImportError``; a library's ``except BaseException``) does
    not make :func:`main` report a failure, or carry on, after the user pressed Ctrl-C."""
    arrived.append(signum)
    raise KeyboardInterrupt


def _interrupt(signum: int) -> BaseException:
    """The exception :func:`main` reports for a signal that arrived (Ctrl-C or SIGTERM)."""
    return KeyboardInterrupt() if signum == signal.SIGINT else _Terminated(signum)


def _outcome(error: BaseException) -> tuple[str, int]:
    """The line to print for an error that ends the command, and the exit status (:data:`EXIT_STATUSES`)."""
    if isinstance(error, UsageError):
        return f"error: {error}", EXIT_BAD_INPUT
    if isinstance(error, _Terminated):
        return INTERRUPTED_LINES[signal.SIGTERM], 128 + signal.SIGTERM
    if isinstance(error, KeyboardInterrupt):
        return INTERRUPTED_LINES[signal.SIGINT], 128 + signal.SIGINT
    if isinstance(error, INPUT_ERRORS):
        return f"error: {_message(error)}", EXIT_BAD_INPUT
    what = "the computation failed" if isinstance(error, COMPUTATION_ERRORS) else "internal error"
    return (f"error: {what} ({type(error).__name__}: {_message(error) or 'no message'}); rerun with --debug for "
            "the traceback, and please report it", EXIT_FAILED)


#: Suffixes of the files the commands read: a value of a multi-value option with one of these is a file it took.
FILE_SUFFIXES = (".csv", ".nc", ".toml")


def _options_taken(parser: argparse.ArgumentParser, words: Sequence[str] | None = None, *,
                   multi_value: bool = True) -> set[str]:
    """The options, of every command (of those among ``words``, if given: the command line's, so that only the verb
    used has its options added), that take several values (``--free E tau0``, ``--dx 1e-6 2e-6``); with
    ``multi_value=False`` every option."""
    found = set()
    for action in parser.filled()._actions:  # noqa: SLF001 - argparse keeps its actions there
        if action.option_strings and (action.nargs in ("+", "*") or not multi_value):
            found.update(action.option_strings)
        for name, sub in action.choices.items() if isinstance(action, argparse._SubParsersAction) else ():
            if words is None or name in words:
                found |= _options_taken(sub, multi_value=multi_value)
    return found


def _file_taken_as_value(argv: Sequence[str]) -> str:
    """A hint for a usage error: which multi-value option took a file as one of its values (``--free tau0 run.csv``:
    argparse gives every word up to the next option to ``--free``), and how to write it; or which option came after
    ``--`` (``--free tau0 -- run.csv --out o``: every word after ``--`` is a file, and ``--out`` was "required");
    "" if neither."""
    argv, parser = list(argv), build_parser()
    separator = argv.index("--") if "--" in argv else len(argv)
    options = _options_taken(parser, argv[:separator], multi_value=False)
    after = [token.split("=", 1)[0] for token in argv[separator + 1:] if token.split("=", 1)[0] in options]
    if after:
        return (f" ({after[0]} comes after `--`, which ends the options: every word after it is taken as a file; write "
                f"the options before `--`)")
    multi = _options_taken(parser, argv[:separator])
    option = None
    for token in argv[:separator]:
        if token.startswith("--"):
            option = token.split("=", 1)[0] if token.split("=", 1)[0] in multi else None
        elif option is not None and (os.path.isfile(token) or token.lower().endswith(FILE_SUFFIXES)):
            return (f" ({option} took {token!r}, a file, as one of its values: write the file before {option}, or "
                    f"{option} and its values last)")
    return ""


def _unknown_option(argv: Sequence[str], text: str) -> str:
    """A hint for a usage error that does not name it: a word before ``--`` written as an option that no command used
    takes (``--scen A``: options are not abbreviated, and argparse answered only "the following arguments are
    required: --scenario"); "" if none, or if the error names it already."""
    argv = list(argv)
    before = argv[:argv.index("--")] if "--" in argv else argv
    options = _options_taken(build_parser(), before, multi_value=False)
    unknown = [word.split("=", 1)[0] for word in before
               if word.startswith("--") and len(word) > 2 and word.split("=", 1)[0] not in options]
    if not unknown or re.search(rf"(?<![\w-]){re.escape(unknown[0])}(?![\w-])", text):  # (named whole: --scen is
        return ""  # not named by "--scenario")
    return (f" ({_one_line(_cut(unknown[0]))} is no option of this command; options are written whole, not "
            "abbreviated: --help lists them)")


def _silence_stdout() -> None:
    """Point stdout at the null device, so that the interpreter's final flush does not raise again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # no real file descriptor (captured in a test): nothing to flush
        pass


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``mdr-events``; returns the exit status (:data:`EXIT_STATUSES`).

    An error prints one line on stderr (``mdr-events: error: ...``); with ``--debug`` it is re-raised with
    its traceback (a usage error excepted). SIGTERM is handled like Ctrl-C while the command runs: the file
    being written is removed (its temporary file), and the status is 143.
    """
    handles_sigterm = threading.current_thread() is threading.main_thread()  # signals reach the main thread only
    arrived: list[int] = []  # the signals that reached the handlers while the command ran (some code may catch them)
    previous = signal.signal(signal.SIGTERM, functools.partial(_on_sigterm, arrived)) if handles_sigterm else None
    # (Ctrl-C's handler is replaced only where it is Python's own: one ignored, as in a background job, stays so)
    previous_int = signal.getsignal(signal.SIGINT) if handles_sigterm else None
    if previous_int is signal.default_int_handler:
        signal.signal(signal.SIGINT, functools.partial(_on_sigint, arrived))
    swallowed = _SwallowedInterrupts()
    if handles_sigterm:
        swallowed.__enter__()
    debug = False
    try:
        with stdout_named():  # (its write errors name it, --help's too; flushed here, not at the interpreter's exit)
            args = build_parser().parse_args(argv)
            debug = args.debug
            if getattr(args, "key", None) is not None:
                from mdr_events.theory import symbolic

                symbolic.relation(args.key)  # an unknown (or empty) key is bad input before anything is printed
            if args.command is not None and getattr(args, "figures", True):  # (derive draws none: no matplotlib)
                import matplotlib

                matplotlib.use("Agg")  # the CLI writes figures to files only: no window, whatever the user's default
            status = args.run(args)
        swallowed.settle()
        if swallowed.interrupts:  # the interpreter swallowed it (garbage collection): the command was interrupted
            raise swallowed.interrupts[0]
        if arrived:  # code the command ran caught it and went on: the command was interrupted all the same
            raise _interrupt(arrived[0])
    except BrokenPipeError:  # the reader has gone (`| head`): nothing more to say, and no one to say it to
        _silence_stdout()
        return EXIT_BROKEN_PIPE
    except (Exception, KeyboardInterrupt, _Terminated) as error:
        swallowed.settle()
        if swallowed.interrupts:
            error = swallowed.interrupts[0]
        elif arrived and not isinstance(error, (KeyboardInterrupt, _Terminated)):  # an error it caused (or met)
            error = _interrupt(arrived[0])
        if debug and not isinstance(error, UsageError):
            raise
        text, code = _outcome(error)
        if isinstance(error, UsageError):
            words = sys.argv[1:] if argv is None else list(argv)
            text += _file_taken_as_value(words) or _unknown_option(words, text)
        progress(f"mdr-events: {_one_line(text)}")
        return code
    finally:
        if handles_sigterm:
            swallowed.__exit__()
            signal.signal(signal.SIGTERM, signal.SIG_DFL if previous is None else previous)
            if previous_int is signal.default_int_handler:
                signal.signal(signal.SIGINT, previous_int)
    return 0 if status is None else int(status)


def _forget_handled_interrupt() -> None:
    """Clear CPython's note of an unhandled Ctrl-C, once :func:`main` has handled every interrupt.

    A ``KeyboardInterrupt`` that leaves code run by ``exec`` of a string (``dataclasses`` builds its methods so while
    a module is imported) makes CPython note it as unhandled, even when :func:`main` catches it later; the interpreter
    then ends itself by SIGINT (a parent saw -2, not the 130 the line announced: ``python -m mdr_events.app.cli
    validate ...`` interrupted 0.35 s after its start, 5 times in 10). An ``exec`` of a string that completes clears
    the note (CPython's ``run_eval_code_obj`` resets it before it runs the code).
    """
    exec("", {})  # noqa: S102 - an empty string: nothing is run


def console_main() -> int:
    """The console script ``mdr-events``: :func:`main`; after an interrupt, what the interpreter's shutdown would
    print (a storage library's pending tasks destroyed, thousands of lines after a SIGTERM mid-sweep) is not shown:
    the one line said what happened."""
    status = main()
    for signum in (signal.SIGINT, signal.SIGTERM):  # (the work is done: a signal now would end it silently with 130)
        signal.signal(signum, signal.SIG_IGN)
    _forget_handled_interrupt()
    if status in (128 + signal.SIGINT, 128 + signal.SIGTERM) and sys.stderr is not None:  # (2>&-: none to silence)
        sys.stderr.flush()
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stderr.fileno())
    return status


if __name__ == "__main__":  # pragma: no cover
    sys.exit(console_main())
