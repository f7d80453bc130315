"""What every hostile round asserts of a refusal, written once (imported by the rounds' modules in tests/): the API's
one line naming the argument and what is allowed, with no warning before it, and the CLI's one line on stderr with
exit status 2."""

from __future__ import annotations

import warnings

import pytest

from mdr_events.app.cli import main


def one_line_naming(call, named: str, errors=(ValueError, TypeError)) -> str:
    """The message of what ``call`` raises with every warning an error: one line, naming ``named`` and what is
    allowed, and no warning before it."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(errors) as caught:
            call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message, message
    return message


def cli_one_line(capsys, argv: list[str]) -> str:
    """The one line ``mdr-events argv`` prints on stderr, exiting 2."""
    status = main(argv)
    err = capsys.readouterr().err
    assert status == 2 and err.count("\n") == 1 and err.startswith("mdr-events: error:"), (status, err)
    return err
