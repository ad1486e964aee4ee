"""Angular impulse and angular momentum: J = ∫τ dt = ΔL, L = Iω. One module per model:

- balance: a constant torque, τΔt = I(ω₁ − ω₀), any four of I, ω₀, ω₁, τ, Δt giving the fifth;
- changing_inertia: inertia that changes with no external torque (the skater, the diver): I₀ω₀ = I₁ω₁;
- sampled: a torque that varies in time, sampled: J by quadrature, then ω₁ = ω₀ + J/I;
- meeting: particles and bodies that meet the body, L about the axis conserved;
- momentum: angular momentum and impulse given as such, L₀ = Iω₀, L₁ = Iω₁, J = L₁ − L₀ = τΔt;
- braked: a constant torque against brakes and rubbing faces, I dω/dt = τ − τ_f·sgn ω;
- point: --at r, a point of the body before and after;

and pick, whose ``impulse`` (the command's library function) picks one by what is given.
"""

from taucli.scenes.impulse.balance import UNKNOWNS, solve_balance
from taucli.scenes.impulse.changing_inertia import solve_changing_inertia
from taucli.scenes.impulse.pick import impulse
from taucli.scenes.impulse.sampled import solve_profile

__all__ = ["UNKNOWNS", "impulse", "solve_balance", "solve_changing_inertia", "solve_profile"]
