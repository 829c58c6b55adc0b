'use strict';
/* Grading a results file with `rotorcert vectors check` (the same judge as `rotorcert certify`). */

const fs = require('fs');
const os = require('os');
const path = require('path');
const {spawnSync} = require('child_process');

const GOOD = ['PASS', 'QUALITY_WARNING'];

/** rotorcert could not be run, or could not grade the file (exit status 2: a usage error, an
 *  unreadable or malformed results or vector file). */
class CheckError extends Error {
  constructor(message) { super(message); this.name = 'CheckError'; }
}

/** One clause of a certificate (report.json of `vectors check --out`). */
class ClauseResult {
  constructor(entry) {
    const worst = entry.worst || {};
    this.entry = entry;
    this.id = entry.id;
    this.level = entry.level;
    this.outcome = entry.outcome;
    this.claimed = Boolean(entry.claimed);
    this.op = worst.op;
    this.input = worst.input;
    this.label = worst.label;
    this.errorEps = worst.error_eps;
    this.detail = worst.detail;
    this.conventions = entry.conventions || [];
    this.note = entry.note || '';
  }

  /** One paragraph as the certificate prints it: outcome, error, op [case], input, conventions. */
  describe() {
    let head = `${this.id} ${this.outcome}`;
    if (typeof this.errorEps === 'number') head += `  ${this.errorEps.toPrecision(3)} eps`;
    if (this.op) head += `  ${this.op} [${this.label}]`;
    const lines = [head];
    if (this.input) lines.push('    input:  ' + this.input);
    if (this.detail) lines.push('    detail: ' + this.detail);
    if (this.note) lines.push('    note:   ' + this.note);
    if (this.conventions.length) lines.push('    consistent with convention: ' + this.conventions.join(' '));
    return lines.join('\n');
  }
}

/** The outcome of `rotorcert vectors check`: exitCode (0 every claimed clause PASS or
 *  QUALITY_WARNING, 1 otherwise), output (the printed certificate), report (report.json),
 *  reportDir (null when it was a temporary directory). */
class Certificate {
  constructor(exitCode, output, report, reportDir) {
    this.exitCode = exitCode;
    this.output = output;
    this.report = report;
    this.reportDir = reportDir;
  }

  get passed() { return this.exitCode === 0; }

  clauses() {
    const impls = (this.report && this.report.implementations) || [];
    return impls.flatMap((impl) => (impl.clauses || []).map((c) => new ClauseResult(c)));
  }

  /** The claimed clauses that did not pass (FAIL, NOT_SUPPORTED, ...): why the exit status is 1. */
  failedClauses() { return this.clauses().filter((c) => c.claimed && !GOOD.includes(c.outcome)); }

  claim() {
    const impls = (this.report && this.report.implementations) || [];
    return impls.length ? impls[0].claim || '' : '';
  }
}

/** Runs `rotorcert vectors check RESULTS [--vectors DIR] --out OUT` and returns the Certificate.
 *  options: rotorcert (the executable, default 'rotorcert' on PATH), out (default: a temporary
 *  directory, read and removed), vectors, timeoutMs. Throws CheckError when rotorcert cannot
 *  grade the file (exit 2) or cannot be run. */
function check(resultsPath, options = {}) {
  const exe = options.rotorcert || 'rotorcert';
  const tmp = options.out ? null : fs.mkdtempSync(path.join(os.tmpdir(), 'rotorcert-check-'));
  const out = options.out || tmp;
  try {
    const args = ['vectors', 'check', resultsPath, '--out', out];
    if (options.vectors) args.push('--vectors', options.vectors);
    const proc = spawnSync(exe, args, {encoding: 'utf8', timeout: options.timeoutMs || 600000, maxBuffer: 64 << 20});
    const cmd = [exe, ...args].join(' ');
    if (proc.error) throw new CheckError(`${cmd}: ${proc.error.message}`);
    const output = (proc.stdout || '') + (proc.stderr || '');
    if (proc.status !== 0 && proc.status !== 1)
      throw new CheckError(`${cmd} exited with ${proc.status === null ? 'signal ' + proc.signal : proc.status}:\n${output}`);
    let report = null;
    try { report = JSON.parse(fs.readFileSync(path.join(out, 'report.json'), 'utf8')); } catch (e) { report = null; }
    return new Certificate(proc.status, output, report, tmp ? null : out);
  } finally {
    if (tmp) fs.rmSync(tmp, {recursive: true, force: true});
  }
}

module.exports = {check, Certificate, ClauseResult, CheckError};
