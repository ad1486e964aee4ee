"""The gyro scene: a spinning body whose axis turns.

One module per model, under scene.py, which reads the options and picks one:

    top.py      a top or gyroscope on a pivot under its weight (or a given torque): the
                precession rate, the exact steady rates (roots.py), the orbit of the centre of
                mass and the pivot's force; steps.py writes its steps
    machine.py  a rotor on a machine whose axis is turned at a given rate (a ship or aircraft in
                a turn or pitching, a vehicle on a curve): the gyroscopic couple Iω_sΩ, its
                effect in words, the bearing forces
"""

from taucli.scenes.gyro.roots import approximation_error, least_spin, precession_roots
from taucli.scenes.gyro.scene import gyro

__all__ = ["approximation_error", "gyro", "least_spin", "precession_roots"]
