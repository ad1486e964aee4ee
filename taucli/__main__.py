"""``taucli`` and ``python -m taucli``: help and version at once, else the command line.

A help text is written from the commands' tables (taucli.front.help) without importing typer, which
alone takes longer than a help should. Everything else goes to taucli.front.cli.
"""

import sys

from taucli.front import help, streams


SYMBOLS = "²½αωθτ·√−→₁≤μ"  # what taucli's text uses beyond ASCII


def _speakable(stream) -> None:
    """A stream whose encoding cannot write taucli's symbols (PYTHONIOENCODING=ascii, a Latin-1
    console) writes UTF-8 instead: JSON is UTF-8 by its standard (RFC 8259), and a garbled ² is
    better than a run that dies on it."""
    encoding = getattr(stream, "encoding", None)
    if not encoding or not hasattr(stream, "reconfigure"):
        return
    try:
        SYMBOLS.encode(encoding)
    except (UnicodeEncodeError, LookupError):
        stream.reconfigure(encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else list(argv)
    _speakable(sys.stdout)
    _speakable(sys.stderr)
    stdout = streams.guarded(sys.stdout)  # closed or full: one line and exit 74, not a traceback
    try:
        answered = help.answer(args, stdout, sys.stderr)
    except streams.OutputFailed as err:
        return streams.failed(err, sys.stderr)
    if answered is not None:
        return answered
    from taucli.front.cli import main as run  # deferred: typer (about 25 ms), which help and --version do without

    return run(args)


if __name__ == "__main__":
    sys.exit(main())
