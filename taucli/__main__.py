"""``taucli`` and ``python -m taucli``: help and version at once, else the command line.

A help text is written from the commands' tables (taucli.help) without importing typer, which
alone takes longer than a help should. Everything else goes to taucli.cli.
"""

import sys


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else list(argv)
    from taucli import help

    answered = help.answer(args, sys.stdout, sys.stderr)
    if answered is not None:
        return answered
    from taucli.cli import main as run

    return run(args)


if __name__ == "__main__":
    sys.exit(main())
