"""The names the command line offers: shapes and their axes, methods, pulley shapes, bodies.

Plain data, so that ``--help`` and the completion scripts need no solver. Each list is tied
to the solver table it mirrors by tests/writing/test_layers.py.
"""

# Shape -> its axes, the default first (scenes.inertia.SHAPES).
SHAPE_AXES: dict[str, tuple[str, ...]] = {
    "point": ("distance",),
    "ring": ("central", "diameter"),
    "disc": ("central", "diameter"),
    "tube": ("central", "diameter"),
    "sphere": ("central",),
    "shell": ("central",),
    "thick-shell": ("central",),
    "rod": ("center", "end"),
    "plate": ("normal", "center-width", "center-height", "edge-width", "edge-height"),
    "box": ("height", "width", "depth"),
    "cone": ("central",),
}
SHAPE_NAMES = tuple(SHAPE_AXES)
ROLLING_BODIES = ("sphere", "shell", "disc", "cylinder", "ring", "hoop")  # scenes.rolling.K2
METHOD_NAMES = ("auto", "exact", "euler", "rk4", "rk45")  # "auto", "exact", *numerics.METHODS
QUADRATURE_NAMES = ("auto", "trapezoid", "simpson")  # scenes.impulse rules
PULLEY_SHAPES = ("disc", "ring")  # scenes.atwood.Pulley.SHAPE_FACTORS
BENCH_SCENES = ("spin-down", "impulse")  # bench.SCENES
BENCH_SCENES += ("pendulum",)  # (#19)
SHELLS = ("bash", "zsh", "fish")  # completions.FILE_NAMES
FORMATS = ("md", "latex", "html", "csv")  # --format (#36): formats.py and latex.py write them
