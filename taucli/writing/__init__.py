"""Writing an answer: the Report a solver returns, and every way it is shown.

Owns Report / Value / Step / Table, the contract between the solvers and the writers (report);
equations as text (display); Markdown, HTML and CSV (formats) and LaTeX (latex) documents; the
human view, --json, --get and --to (render); terminal and file charts (plot).

May import: taucli.core, taucli.quantities (render converts for --to, plot finds its cache
folder). rich, plotille and matplotlib are imported only where they draw.
"""
