'use strict';
/* One call of a library function on one vector, and the one status rule (RESULT-2), the same as
 * the Python package's (rotorcert_vectors.outcome):
 *
 *   the function threw (the library refused the input)        -> DOMAIN_ERROR, every output NaN
 *   it returned null or undefined (its way of refusing)         -> DOMAIN_ERROR, every output NaN
 *   every output component is NaN                               -> DOMAIN_ERROR (RESULT-2)
 *   anything else                                               -> OK with the outputs as computed
 *   it threw DidNotReturn (the caller stopped a call that never returned)
 *                                                               -> raw status byte 255: FAIL
 *
 * A ReferenceError or TypeError, an AdapterError, and a wrong number of output values are defects
 * of the code that maps the library onto the ABI, not refusals: call() throws AdapterError for them
 * (runFile adds the vector and its input), so that no certificate grades a typo as a DOMAIN_ERROR. */

const {OUTPUTS} = require('./abi');
const {hexfloat} = require('./hexfloat');

const OK = 'OK';
const DOMAIN_ERROR = 'DOMAIN_ERROR';
const DID_NOT_RETURN = 255;  // raw status byte (conformance/VECTORS.md: anything but OK and DOMAIN_ERROR fails)

/** Thrown by a function that ran a library call under a time limit and had to stop it. */
class DidNotReturn extends Error {
  constructor(message) { super(message); this.name = 'DidNotReturn'; }
}

/** A defect of the function that calls the library; `vector` is the Vector when known, `cause`
 *  the original error. */
class AdapterError extends Error {
  constructor(message, options = {}) {
    super(message, options.cause === undefined ? undefined : {cause: options.cause});
    this.name = 'AdapterError';
    this.vector = options.vector;
  }
}

/** What one call gave: status ('OK', 'DOMAIN_ERROR' or a raw status byte), outputs ({name:
 *  numbers}), for a refusal `refusal` (why: the error's name, 'returned null', ...), and `modified`
 *  when the call modified its inputs (HYG-1, see watch()). */
class Outcome {
  constructor(status, outputs, refusal = null) {
    this.status = status;
    this.outputs = outputs;
    this.refusal = refusal;
    this.modified = '';
  }

  /** The results-file entry of this outcome (conformance/VECTORS.md), values in hexfloat;
   *  `modified_inputs` when the call modified its inputs (HYG-1). */
  result(vectorId) {
    const out = {};
    for (const [name, values] of Object.entries(this.outputs)) out[name] = values.map(hexfloat);
    const r = {id: vectorId, status: this.status, out};
    if (this.modified) r.modified_inputs = this.modified;
    return r;
  }
}

// HYG-1 (inputs are not modified): the arguments handed to the function, and every library object
// the function builds from them and registers with watch(), are serialised before the call and
// compared after it (every number exactly: -0, NaN and typed arrays included).
const watched = [];
function snapshot(x) {
  return JSON.stringify(x, (k, v) => {
    if (typeof v === 'number') return Object.is(v, -0) ? '-0' : String(v);
    if (ArrayBuffer.isView(v)) return Array.from(v, (c) => (Object.is(c, -0) ? '-0' : String(c)));
    return v;
  });
}

/** Registers library objects an op function builds from its inputs (a THREE.Quaternion made of
 *  the input array, say), so that a library call that modifies them in place is reported (HYG-1).
 *  Returns the first object. */
function watch(...objects) {
  for (const o of objects) watched.push([o, snapshot(o)]);
  return objects[0];
}

function modifiedInputs(args, before) {
  if (snapshot(args) !== before) return "the function's input arrays were modified";
  for (let i = 0; i < watched.length; ++i) {
    const [o, was] = watched[i];
    const now = snapshot(o);
    if (now !== was) return `watched input object ${i} (${(o && o.constructor && o.constructor.name) || typeof o}) was modified in place: ${was} before, ${now} after`;
  }
  return '';
}

function nanOutputs(op) {
  const out = {};
  for (const [name, stride] of OUTPUTS[op]) out[name] = new Array(stride).fill(NaN);
  return out;
}

function flatten(v) {
  if (typeof v === 'number') return [v];
  return Array.from(v, Number);
}

function fnName(fn, op) { return (fn && fn.name) || op; }

/** The Outcome of fn(...args) for ABI op `op` under the status rule, with `modified` set when the
 *  call modified its inputs (HYG-1); throws AdapterError for a defect of fn. */
function call(op, fn, args) {
  watched.length = 0;
  const before = snapshot(args);
  const outcome = callOnce(op, fn, args);
  outcome.modified = modifiedInputs(args, before);
  watched.length = 0;
  return outcome;
}

function callOnce(op, fn, args) {
  const outs = OUTPUTS[op];
  let result;
  try {
    result = fn(...args);
  } catch (e) {
    if (e instanceof DidNotReturn) return new Outcome(DID_NOT_RETURN, nanOutputs(op), 'did not return: ' + e.message);
    if (e instanceof AdapterError) throw e;
    if (e instanceof ReferenceError || e instanceof TypeError)
      throw new AdapterError(`${fnName(fn, op)} threw ${e.name}: ${e.message}`, {cause: e});
    return new Outcome(DOMAIN_ERROR, nanOutputs(op), (e && e.constructor && e.constructor.name) || typeof e);
  }
  if (result === null || result === undefined) return new Outcome(DOMAIN_ERROR, nanOutputs(op), 'returned ' + result);
  if (outs.length === 1) {
    result = [result];
  } else if (!Array.isArray(result) || result.length !== outs.length) {
    throw new AdapterError(`${fnName(fn, op)} returned ${String(result)}: ${op} has ${outs.length} outputs ` +
                           `(${outs.map(([n]) => n).join(', ')}), return them as an array`);
  }
  const arrays = {};
  outs.forEach(([name, stride], i) => {
    let values;
    try {
      values = flatten(result[i]);
    } catch (e) {
      throw new AdapterError(`${fnName(fn, op)} returned ${String(result[i])} for ${name}: not numbers`, {cause: e});
    }
    if (values.length !== stride)
      throw new AdapterError(`${fnName(fn, op)} returned ${values.length} values for ${name}, which has ${stride} (LAYOUT-1)`);
    arrays[name] = values;
  });
  if (Object.values(arrays).every((values) => values.every((x) => Number.isNaN(x)))) return new Outcome(DOMAIN_ERROR, arrays);
  return new Outcome(OK, arrays);
}

/** EXP-2 (op log_exp_round_trip): exp of what log returned; DOMAIN_ERROR (a thrown RangeError)
 *  when log refuses (throws, returns null, or returns all NaN). */
function roundTrip(log, exp) {
  return function log_exp_round_trip(q) {
    const v = log(q);
    if (v === null || v === undefined || flatten(v).every((c) => Number.isNaN(c))) throw new RangeError('log refused the input');
    return exp(v);
  };
}

module.exports = {OK, DOMAIN_ERROR, DID_NOT_RETURN, DidNotReturn, AdapterError, Outcome, call, roundTrip, watch};
