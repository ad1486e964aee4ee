"""Pure solvers: SI floats in, a Report out. No pint, no rich, no I/O."""
