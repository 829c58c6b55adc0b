"""Exact number text of the vector and results files (conformance/VECTORS.md)."""
import math

_SPECIAL = {"nan": math.nan, "-nan": math.nan, "inf": math.inf, "-inf": -math.inf}


def parse_hex(text):
    """The value of a vector's "hex" string: C99 / Python hexfloat (exact), or nan, -nan, inf, -inf.
    binary32 values are exact in a Python float, so one parser serves both formats."""
    special = _SPECIAL.get(text)
    return special if special is not None else float.fromhex(text)


def hexfloat(x):
    """A number as the results file wants it: Python's float.hex() (exact), or nan / inf / -inf."""
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x.hex()
