"""The front ends: the command line (cli, usage: the fix for a misread command line), batch
(JSON lines), the Python API's functions (api), --help and the docs' option tables (help), the
completion scripts (completions), bench and completions as commands (tools, bench).

No physics and no reading rules of their own: each is made from the commands' tables.
May import: every layer below (core, numerics, quantities, writing, options, scenes, answering,
fit).
"""
