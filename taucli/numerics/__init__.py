"""Numerical methods, with no physics and no taucli import: time steppers with event location
(steppers), quadrature of samples and functions, tanh-sinh included (quadrature), bracketing and polishing
roots (roots), complete and incomplete elliptic integrals and Jacobi functions (elliptic), and
products without rounding error (exact).

May import: taucli.core only (today, nothing at all). Imported by the scenes, the answering layer
(--find's root search) and the benchmarks.
"""
