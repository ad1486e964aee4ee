"""Pure solvers: SI floats in, a Report out. No pint, no rich, no I/O.

A scene with several models is a package of one module per model (spin, atwood, rolling,
impulse, pendulum, gyro, drive); each names its results from its table (taucli.options).
May import: taucli.core, numerics, quantities.kinds (bounds, no pint), writing.report, options.
"""
