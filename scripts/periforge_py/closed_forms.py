"""Closed forms the validation scripts judge runs and FE references against."""


def timoshenko_tip_force(u, length, e, nu, b, h):
    """Tip force of Timoshenko's cantilever (rectangular section b x h, clamped at x = 0) for a tip deflection u,
    shear coefficient 10(1 + nu)/(12 + 11 nu) (Cowper)."""
    k = 10 * (1 + nu) / (12 + 11 * nu)
    return u / (length ** 3 / (3 * e * b * h ** 3 / 12) + length / (k * e / (2 * (1 + nu)) * b * h))
