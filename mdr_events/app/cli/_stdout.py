"""The command's standard output named in its write errors.

A command prints what it wrote and its summaries on stdout. Written to a full device (``> /dev/full``), an error
there read ``mdr-events: error: [Errno 28] No space left on device``, after a run whose files were all written: it
did not say what could not be written (round twenty-three). While a command runs, :func:`stdout_named` puts a
:class:`NamedOutput` in ``sys.stdout``: its write errors (the closed pipe's excepted, :func:`~mdr_events.app.cli.main`
ends those silently) name the standard output and what it must take, and the command flushes it before it ends, so
that an error meets it there rather than in the interpreter's shutdown: the help and the version (``--help >
/dev/full`` ended 0 with nothing written, round twenty-four) as the commands' text. Text the stream's encoding cannot
write (``PYTHONIOENCODING=ascii``) is refused naming the encoding.
"""

from __future__ import annotations

import contextlib
import sys
from typing import Iterator, TextIO

__all__ = ["NamedOutput", "stdout_named"]

#: The name the errors give the standard output (in place of a file's path).
STDOUT_NAME = "<standard output>"


class NamedOutput:
    """``stream`` (the command's stdout), whose write errors name it.

    Parameters
    ----------
    stream : TextIO
        The standard output it writes to.
    """

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        #: The first write error, raised again by :meth:`flush`: a caller may swallow it (argparse's ``--help``
        #: ignores OSError: ``--help > /dev/full`` ended 0 with nothing written, round twenty-four).
        self.failed: OSError | None = None

    def write(self, text: str) -> int:
        """Write ``text`` to the stream.

        Parameters
        ----------
        text : str
            What to write.

        Returns
        -------
        int
            The characters written.

        Raises
        ------
        OSError
            The stream's error, naming the standard output and what is allowed (``BrokenPipeError`` as it is).
        ValueError
            Text the stream's encoding cannot write (``PYTHONIOENCODING=ascii``: the relations' ``⋅``), naming the
            standard output, its encoding and what is allowed.
        """
        try:
            with _named():
                return self.stream.write(text)
        except OSError as error:
            self.failed = self.failed or error
            raise
        except UnicodeEncodeError as error:  # (round twenty-four: "'ascii' codec can't encode character ...")
            raise ValueError(f"{STDOUT_NAME} of encoding {error.encoding!r} cannot write "
                             f"{error.object[error.start:error.end]!r} (the text is Unicode); allowed: a standard output "
                             "that takes UTF-8 (PYTHONIOENCODING=utf-8, or a UTF-8 locale)") from None

    def flush(self) -> None:
        """Flush the stream.

        Raises
        ------
        OSError
            The stream's error, or the first of its writes (:attr:`failed`, cleared once raised), naming the
            standard output and what is allowed (``BrokenPipeError`` as it is).
        """
        with _named():
            self.stream.flush()
        failed, self.failed = self.failed, None  # (raised once: raised again, its traceback would grow each time)
        if failed is not None:
            raise failed

    def __getattr__(self, name: str):
        return getattr(self.stream, name)


@contextlib.contextmanager
def _named() -> Iterator[None]:
    try:
        yield
    except BrokenPipeError:
        raise
    except OSError as error:
        raise OSError(error.errno, f"{error.strerror or error}; allowed: a standard output with room for the text (a "
                                   "terminal, a pipe, a file on a device with space)",
                      STDOUT_NAME) from error


@contextlib.contextmanager
def stdout_named() -> Iterator[None]:
    """``sys.stdout`` a :class:`NamedOutput` while the block runs, flushed at its end (none if stdout is closed).

    Yields
    ------
    None
        Nothing: the block prints to ``sys.stdout``.
    """
    original = sys.stdout
    if original is None:  # (started with stdout closed, >&-: print writes nothing)
        yield
        return
    sys.stdout = NamedOutput(original)
    try:
        try:
            yield
        except SystemExit:  # (argparse's --help and --version printed and exit: flushed here, round twenty-four)
            sys.stdout.flush()
            raise
        sys.stdout.flush()
    finally:
        if isinstance(sys.stdout, NamedOutput) and sys.stdout.stream is original:
            sys.stdout = original
