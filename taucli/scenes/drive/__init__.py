"""The drive scene: a motor turning a load through a ratio N with an efficiency η.

One module per model, under scene.py, which reads the options and picks one:

    train.py    the train: the load reflected to the motor (J/N², m r², m(p/2π)²), the load
                torque T/(Nη) or ηT/N, and the motor torque at an acceleration
    motor.py    the run-up from rest: at a constant α (the torque it takes), or under the
                motor's torque–speed line or a constant torque (the time it takes)
    profile.py  a move profile: accelerate, run, decelerate, dwell; peak and RMS torque, power
    loads.py    several loads, each through its own train and efficiency (--load)
    curve.py    an induction motor's run-up on Kloss's torque–slip curve (--motor-curve)
    duty.py     a duty cycle from a table of segments (--segment): RMS torque or power
"""

from taucli.scenes.drive.scene import drive
from taucli.scenes.drive.train import Train

__all__ = ["Train", "drive"]
