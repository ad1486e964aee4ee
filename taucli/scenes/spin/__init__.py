"""The spin-down scene: a wheel on a fixed axle under driving torque, friction and drag.

    I dω/dt = τ_drive − τ_f·sgn(ω) − bω − k|ω|ⁿ·sgn(ω)

One module per model, under scene.py, which reads the options and picks one:

    torque_laws.py     the torques above: closed forms (closed_forms.py) for every combination
                       with n = 2, a stepper otherwise; the stop located as an event
    methods.py         the choice of method, and a fixed step's error against a reference
    constant_alpha.py  rotation at a constant α (--alpha, a target with no body): kinematics,
                       and with a body the torque and energy it takes (kinematics.py: any three
                       of ω₀, ω₁, α, t, θ)
    power.py           a motor of constant power (τ = P/ω)
    energy.py          the kinetic energy, and the work and power of the drive and each loss
    contacts.py        brakes and pressed faces (their torques: taucli.scenes.contact)
    point.py           a point at radius r (taucli.scenes.point)
    steps.py           what the models share: the worked steps of constant-α kinematics

Coulomb friction τ_f is physics, not sgn(ω): the wheel stops at t_stop and stays stopped
while |τ_drive| ≤ τ_f (static friction holds it); only a larger driving torque starts it again,
the other way.
"""

from taucli.scenes.spin.scene import spin_down
from taucli.scenes.spin.steps import Torques
from taucli.scenes.spin.torque_laws import solve

__all__ = ["spin_down", "solve", "Torques"]
