'use strict';
/* Running every vector of an export through an Implementation, from a script or a test. */

const {AdapterError, DID_NOT_RETURN, call} = require('./outcome');
const {Implementation, writeResults} = require('./results');
const {VectorSet} = require('./vectors');

/** [[vector, Outcome]] of one vector file's op function on each of its vectors, in file order. A
 *  defect of fn (AdapterError) is re-thrown with the vector's id and its input in hexfloat. */
function runFile(vectorFile, fn) {
  const outcomes = [];
  for (const vector of vectorFile.vectors) {
    try {
      outcomes.push([vector, call(vectorFile.op, fn, vector.arguments())]);
    } catch (e) {
      if (!(e instanceof AdapterError)) throw e;
      throw new AdapterError(`${vector.id} (${vector.comment}): ${vectorFile.op}(${vector.describeInputs()}): ${e.message}`,
                             {vector, cause: e.cause === undefined ? e : e.cause});
    }
  }
  return outcomes;
}

function refusalKey(op, outcome) {
  return `${op} ${outcome.status === DID_NOT_RETURN ? 'did not return' : 'refused'}`;
}

/** The outcome of every vector an Implementation answers: results (results-file entries in index
 *  order), refused ({'op refused' / 'op did not return': count}), outcomes (Map: vector id ->
 *  Outcome). */
class Run {
  constructor(implementation, vectorSet) {
    this.implementation = implementation;
    this.vectorSet = vectorSet;
    this.results = [];
    this.refused = {};
    this.outcomes = new Map();
  }

  add(vector, outcome) {
    this.results.push(outcome.result(vector.id));
    this.outcomes.set(vector.id, outcome);
    if (outcome.refusal) {
      const key = refusalKey(vector.file.op, outcome);
      this.refused[key] = (this.refused[key] || 0) + 1;
    }
  }

  write(file) {
    writeResults(file, this.vectorSet.directory, this.implementation, this.results, this.implementation.unsupportedOps);
  }
}

/** Runs every vector of `vectors` (a VectorSet, or the export's directory or index.json) of the
 *  implementation's number format whose op it has; writes the results file when resultsPath is
 *  given; returns the Run. */
function run(implementation, vectors, resultsPath) {
  const vectorSet = vectors instanceof VectorSet ? vectors : new VectorSet(vectors);
  const r = new Run(implementation, vectorSet);
  for (const vf of vectorSet.files(implementation.numberFormat, implementation.ops))
    for (const [vector, outcome] of runFile(vf, implementation.ops[vf.op])) r.add(vector, outcome);
  if (resultsPath !== undefined) r.write(resultsPath);
  return r;
}

function usage(description, msg) {
  const text = 'usage: ADAPTER --vectors DIR --out RESULTS.json';
  if (msg) console.error(msg);
  console.error((description ? description + '\n' : '') + text);
}

/** The command line of an adapter script: --vectors DIR --out RESULTS.json (also --vectors=DIR);
 *  returns the exit status (0, or 2 on a usage error). `implementation` is an Implementation, or
 *  a results-file implementation object ({name, version, scalar, description}) with `ops`. */
function runAdapter(argv, description, implementation, ops) {
  const args = {};
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--vectors' || a === '--out') {
      if (i + 1 >= argv.length) { usage(description, a + ' needs a value'); return 2; }
      args[a.slice(2)] = argv[++i];
    } else if (a.startsWith('--vectors=') || a.startsWith('--out=')) {
      const j = a.indexOf('=');
      args[a.slice(2, j)] = a.slice(j + 1);
    } else if (a === '-h' || a === '--help') {
      usage(description);
      return 0;
    } else {
      usage(description, 'unknown argument ' + a);
      return 2;
    }
  }
  if (!args.vectors || !args.out) { usage(description, '--vectors and --out are required'); return 2; }
  const impl = implementation instanceof Implementation ? implementation : Implementation.fromObject(implementation, ops);
  const r = run(impl, args.vectors);
  writeResults(args.out, args.vectors, impl, r.results, impl.unsupportedOps);
  const note = Object.keys(r.refused).sort().map((k) => `${k} ${r.refused[k]}`).join(', ');
  console.log(`${impl.name}: wrote ${r.results.length} results to ${args.out}${note ? ' (' + note + ')' : ''}`);
  return 0;
}

module.exports = {runFile, Run, run, runAdapter, refusalKey};
