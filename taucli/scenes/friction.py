"""What the friction coefficients given mean, one rule for every scene with a contact (atwood's
m2 on its surface, rolling's body on its slope).

- μs decides whether the contact grips (holds, or rolls); μk sets the force once it slides.
- Only μk given: μs is taken equal to it, with a note. Every real pair of surfaces has
  μs ≥ μk, so μk is the least the static coefficient can be. With it, a contact that grips is
  certain to grip for any true μs, and one that slides slides with the one-coefficient textbook
  friction, continuous with gripping at the boundary (μk = μ_min). Assuming it grips instead
  (as rolling once did) would claim a μs ≥ μ_min that nothing given supports, when giving μk
  says the user expects it may slide.
- Only μs given: it still decides. Where the contact slides, what needs μk is null with a note.
- Neither: each scene's textbook default (a smooth surface under atwood's m2; rolling without
  slipping for a rolling body), said in its own note.
"""

from __future__ import annotations

from taucli.writing.report import fmt


def static_coefficient(mu_s: float | None, mu_k: float | None, notes: list[str]) -> float | None:
    """The static coefficient to decide grip or slip with: μs if given, else μk (noted), else None."""
    if mu_s is not None or mu_k is None:
        return mu_s
    notes.append(
        f"no --mu-s: static friction taken as equal to kinetic friction, μs = μk = {fmt(mu_k)}, the least it can be "
        "(μs ≥ μk always); give --mu-s if the surfaces grip better"
    )
    return mu_k


def needs_kinetic(what: str, notes: list[str]) -> None:
    """The note for results left null because the contact slides and μk was not given."""
    notes.append(f"{what}: null, because it slips (the contact slides) and sliding friction needs --mu-k, which was not given")
