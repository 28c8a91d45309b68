"""Roots and maxima found by bracketing, for the recomputations of the answer keys: they
read only a function's values, never the key's formula."""


def bisect(f, low, high, steps=80):
    """A root of f in [low, high], where f changes sign."""
    f_low = f(low)
    assert f_low * f(high) < 0, "the bracket must hold a sign change"
    for _ in range(steps):
        middle = (low + high) / 2
        if f_low * f(middle) <= 0:
            high = middle
        else:
            low, f_low = middle, f(middle)
    return (low + high) / 2


def argmax(f, low, high, h=1e-6):
    """Where a smooth f with one maximum in [low, high] peaks: f' changes sign."""
    return bisect(lambda x: f(x + h) - f(x - h), low, high)
