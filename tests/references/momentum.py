"""Angular momentum and impulse given as such (impulse --momentum0, --momentum1, --impulse), at 50 digits.

A body of fixed moment of inertia I about a fixed axis, a torque τ acting for Δt:

    L₀ = I ω₀,   L₁ = I ω₁,   J = ∫τ dt = L₁ − L₀,   J = τ Δt (τ constant, or its mean)

Four equations in eight quantities (L₀, L₁, J, τ, Δt, I, ω₀, ω₁): any four independent ones given
fix the rest. Here each is found from the givens in closed form at 90 digits, in the order a
book would go (the momenta, then their change, then the torque or the time, then the speeds):

    J = L₁ − L₀  or  τΔt;   L₁ = L₀ + J;  L₀ = L₁ − J;   τ = J/Δt;  Δt = J/τ;
    ω = L/I;  I = L/ω  (or J/(ω₁ − ω₀));  KE = L²/(2I) = ½Iω²;
    KE₁ − KE₀ = J (ω₀ + ω₁)/2 = τ θ  (the work of a constant torque over θ = (ω₀ + ω₁)Δt/2).

Nothing is assumed: a quantity the givens do not fix is None.
"""

from __future__ import annotations

from references import DPS, mp, mpf

WORK = DPS + 40


def momentum(*, L0=None, L1=None, J=None, torque=None, duration=None, inertia=None, omega0=None, omega1=None) -> dict:
    """Every quantity the givens fix (a dict of mpf at 50 digits, None where not fixed)."""
    with mp.workdps(WORK):
        q = {k: (None if v is None else mpf(v)) for k, v in dict(L0=L0, L1=L1, J=J, torque=torque, duration=duration,
                                                               inertia=inertia, omega0=omega0, omega1=omega1).items()}
        for _ in range(4):  # each pass fills what the last one made known; four passes reach every chain of these rules
            I, w0, w1 = q["inertia"], q["omega0"], q["omega1"]
            for L, w in (("L0", "omega0"), ("L1", "omega1")):
                if q[L] is None and I is not None and q[w] is not None:
                    q[L] = I * q[w]
                if q[w] is None and I is not None and q[L] is not None:
                    q[w] = q[L] / I
                if q["inertia"] is None and q[L] is not None and q[w]:
                    q["inertia"] = q[L] / q[w]
            if q["J"] is None and q["L0"] is not None and q["L1"] is not None:
                q["J"] = q["L1"] - q["L0"]
            if q["J"] is None and q["torque"] is not None and q["duration"] is not None:
                q["J"] = q["torque"] * q["duration"]
            if q["J"] is not None:
                if q["L1"] is None and q["L0"] is not None:
                    q["L1"] = q["L0"] + q["J"]
                if q["L0"] is None and q["L1"] is not None:
                    q["L0"] = q["L1"] - q["J"]
                if q["torque"] is None and q["duration"] is not None:
                    q["torque"] = q["J"] / q["duration"]
                if q["duration"] is None and q["torque"]:
                    q["duration"] = q["J"] / q["torque"]
                if q["inertia"] is None and q["omega0"] is not None and q["omega1"] is not None and q["omega1"] != q["omega0"]:
                    q["inertia"] = q["J"] / (q["omega1"] - q["omega0"])
        I, w0, w1 = q["inertia"], q["omega0"], q["omega1"]
        q["delta_omega"] = q["J"] / I if q["J"] is not None and I is not None else None
        q["KE0"] = q["L0"] ** 2 / (2 * I) if q["L0"] is not None and I is not None else None
        q["KE1"] = q["L1"] ** 2 / (2 * I) if q["L1"] is not None and I is not None else None
        work = q["J"] * (w0 + w1) / 2 if None not in (q["J"], w0, w1) else None
        q["work"] = work  # KE₁ − KE₀
    with mp.workdps(DPS):
        return {k: (None if v is None else +v) for k, v in q.items()}
