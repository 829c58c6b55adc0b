"""One call of a library function on one vector, and the one status rule (RESULT-2).

A library without a status channel gets one, the same for every adapter and test suite:

  - the function raised an exception (the library refused the input)   -> DOMAIN_ERROR, every output NaN
  - the function returned None (its way of refusing)                     -> DOMAIN_ERROR, every output NaN
  - it returned something that is not a real number (a complex root)     -> DOMAIN_ERROR, every output NaN
  - every output component is NaN                                        -> DOMAIN_ERROR (RESULT-2)
  - anything else                                                        -> OK with the outputs as computed
  - the call never returned: the caller ran it under a time limit and raised DidNotReturn
                                                                         -> raw status byte 255, which
                                                    `vectors check` grades FAIL: neither OK nor a refusal

NameError, AttributeError, ImportError and KeyError, a wrong number of outputs, and AdapterError
raised by the function itself are defects of the code that maps the library onto the ABI, not
refusals: `call` raises AdapterError for them (run_file adds the vector and its input), so that no
certificate grades a typo as a DOMAIN_ERROR.
"""
import math
import pickle

from .abi import OUTPUTS

# HYG-1 (inputs are not modified): the inputs handed to the function, and every library object the
# function builds from them and registers with watch(), are pickled before the call and compared
# after it, byte for byte.
_watched = []


def _snapshot(o):
    """The state of an object, to compare after the call: its pickle, or (for an object that does not
    pickle) the repr of its attributes or of itself."""
    try:
        return pickle.dumps(o)
    except Exception:  # noqa: BLE001 - local classes, C objects without pickle support
        return repr(vars(o)) if hasattr(o, "__dict__") else repr(o)


def watch(*objects):
    """Registers library objects an op function builds from its inputs (a Quaternion made of the
    input list, say), so that a library call that modifies them in place is reported (HYG-1).
    Returns the object (or the tuple of them)."""
    for o in objects:
        _watched.append((o, _snapshot(o)))
    return objects[0] if len(objects) == 1 else objects


def _modified(args, args_before):
    """What the call modified: "" or a sentence naming the input."""
    if pickle.dumps(args) != args_before:
        return "the function's input lists were modified"
    for i, (o, before) in enumerate(_watched):
        if _snapshot(o) != before:
            was = pickle.loads(before) if isinstance(before, bytes) else before
            return "watched input object %d (%s) was modified in place: %r before, %r after" % (
                i, type(o).__name__, was, o)
    return ""

OK = "OK"
DOMAIN_ERROR = "DOMAIN_ERROR"
DID_NOT_RETURN = 255  # raw status byte (conformance/VECTORS.md: anything but OK and DOMAIN_ERROR fails)
NAN = math.nan

# Exceptions that are the caller's mistakes, never the library's answer to an input.
DEFECT_TYPES = (NameError, AttributeError, ImportError, KeyError)


class DidNotReturn(BaseException):
    """Raised by a function that ran a library call under a time limit and had to stop it (a
    BaseException, so that no library-refusal handler takes it for a DOMAIN_ERROR)."""


class AdapterError(Exception):
    """A defect of the function that calls the library (see the module docstring); `vector` is the
    Vector it was called on when known, `__cause__` the original exception."""

    def __init__(self, message, vector=None):
        super().__init__(message)
        self.vector = vector


class Outcome:
    """What one call gave: `status` ("OK", "DOMAIN_ERROR" or a raw status byte), `outputs`
    ({output array name: [floats]}) and, for a refusal, `refusal` (why: the exception's type name,
    "returned None", ...)."""

    __slots__ = ("status", "outputs", "refusal", "modified")

    def __init__(self, status, outputs, refusal=None, modified=""):
        self.status, self.outputs, self.refusal, self.modified = status, outputs, refusal, modified

    def result(self, vector_id):
        """The results-file entry of this outcome (conformance/VECTORS.md), values in hexfloat;
        `modified_inputs` when the call modified its inputs (HYG-1)."""
        from .numbers import hexfloat
        r = {"id": vector_id, "status": self.status,
             "out": {name: [hexfloat(x) for x in values] for name, values in self.outputs.items()}}
        if self.modified:
            r["modified_inputs"] = self.modified
        return r

    def __repr__(self):
        return "Outcome(%r, %r%s)" % (self.status, self.outputs, ", refusal=%r" % self.refusal if self.refusal else "")


def _nan_outputs(op):
    return {name: [NAN] * stride for name, stride in OUTPUTS[op]}


def _flatten(value):
    if isinstance(value, (list, tuple)):
        return [float(c) for c in value]
    if hasattr(value, "tolist") and not isinstance(value, (int, float)):  # a numpy array or scalar
        return _flatten(value.tolist())
    return [float(value)]


def call(op, fn, args):
    """The Outcome of fn(*args) for ABI op `op` under the status rule (module docstring), with
    `modified` set when the call modified its inputs (HYG-1, see watch()). Raises AdapterError for
    a defect of fn."""
    del _watched[:]
    args_before = pickle.dumps(args)
    outcome = _call(op, fn, args)
    outcome.modified = _modified(args, args_before)
    del _watched[:]
    return outcome


def _call(op, fn, args):
    outs = OUTPUTS[op]
    try:
        result = fn(*args)
    except DidNotReturn as e:
        return Outcome(DID_NOT_RETURN, _nan_outputs(op), "did not return: %s" % e)
    except AdapterError:
        raise
    except DEFECT_TYPES as e:
        raise AdapterError("%s raised %s: %s" % (getattr(fn, "__name__", op), type(e).__name__, e)) from e
    except Exception as e:  # the library refused the input
        return Outcome(DOMAIN_ERROR, _nan_outputs(op), type(e).__name__)
    if result is None:
        return Outcome(DOMAIN_ERROR, _nan_outputs(op), "returned None")
    if len(outs) == 1:
        result = (result,)
    elif not isinstance(result, (list, tuple)) or len(result) != len(outs):
        raise AdapterError("%s returned %r: %s has %d outputs (%s), return them as a tuple"
                           % (getattr(fn, "__name__", op), result, op, len(outs), ", ".join(n for n, _ in outs)))
    try:
        arrays = {name: _flatten(v) for (name, _), v in zip(outs, result)}
    except (TypeError, ValueError) as e:  # e.g. a complex square root: not a number of the format
        return Outcome(DOMAIN_ERROR, _nan_outputs(op), "returned %s" % type(e).__name__)
    for name, stride in outs:
        if len(arrays[name]) != stride:
            raise AdapterError("%s returned %d values for %s, which has %d (LAYOUT-1)"
                               % (getattr(fn, "__name__", op), len(arrays[name]), name, stride))
    if all(math.isnan(x) for values in arrays.values() for x in values):
        return Outcome(DOMAIN_ERROR, arrays)
    return Outcome(OK, arrays)


def round_trip(log, exp):
    """EXP-2 (op log_exp_round_trip): exp of what log returned; DOMAIN_ERROR when either refuses
    (raises, returns None, or log's output is all NaN)."""
    def log_exp_round_trip(q):
        v = log(q)
        if v is None or all(math.isnan(c) for c in _flatten(v)):
            raise ArithmeticError("log refused the input")
        return exp(list(v))
    return log_exp_round_trip
