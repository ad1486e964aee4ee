"""Numerical methods, with no physics and no taucli import: time steppers with event location and
streaming quadrature (steppers), bracketing and polishing roots (roots), tanh-sinh quadrature
(quadrature), complete and incomplete elliptic integrals and Jacobi functions (elliptic).

May import: taucli.core only (today, nothing at all). Imported by the scenes, the answering layer
(--find's root search) and the benchmarks.
"""
