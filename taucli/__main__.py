"""``taucli`` and ``python -m taucli``: help from the cache when it can, else the Typer app.

A help text depends only on taucli, typer and the terminal's width. Once typer has rendered it,
it is kept (taucli.cache) and printed again without importing typer, which alone takes longer
than a help should. Everything else goes to taucli.cli.
"""

import sys

from taucli.names import COMMAND_NAMES


def help_request(args: list[str]) -> str | None:
    """The command whose help ``args`` ask for ("" for taucli's own), or None."""
    if args == ["--help"]:
        return ""
    if len(args) == 2 and args[1] == "--help" and args[0] in COMMAND_NAMES:
        return args[0]
    return None


def show_help(command: str, args: list[str]) -> int:
    import shutil

    from taucli.cache import help_texts

    key = f"{command}|{shutil.get_terminal_size().columns}"
    store = help_texts()
    text = store.get(key)
    if not isinstance(text, str):
        import contextlib
        import io

        from taucli.cli import main as run

        captured = io.StringIO()
        with contextlib.redirect_stdout(captured):
            status = run(args)
        text = captured.getvalue()
        if status != 0 or not text:
            sys.stdout.write(text)
            return status
        store.put(key, text)
    try:
        sys.stdout.write(text)
        sys.stdout.flush()
    except BrokenPipeError:
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return 0


def main() -> int:
    args = sys.argv[1:]
    command = help_request(args)
    if command is not None:
        return show_help(command, args)
    from taucli.cli import main as run

    return run(args)


if __name__ == "__main__":
    sys.exit(main())
