"""What the benchmarks of bench/ share: the paths, running liggghts-membrane (one
process with its CPU time and a timeout, or a run kept in a folder and reused),
the run cache (a run folder's meta.json, reused while its parameters are the same),
the timings and messages of a run (the log's 'Loop time' lines, the screen's ERROR
and WARNING lines), the frozen executable and input scripts of a sweep, the
parameters of the input scripts (liggghts_membrane.params) and the CSV / context
files a report is made from.

A sweep is plan / run / report: the plan is the list of cases, `run` executes the
missing ones into the cache, and the report (Markdown, PNG) is made from the CSV and
the context file (PREFIX.json: the command, its options and what the CSV does not
hold) that the run step writes; `--from-csv` makes it again from those two files
alone.
"""
import csv
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import time

# the repository (this file is python/liggghts_membrane/bench/common.py) and its bench/
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
HERE = os.path.join(ROOT, "bench")
EXAMPLES = os.path.join(ROOT, "examples", "biaxial")
MESHES = os.path.join(EXAMPLES, "meshes")
EXE = os.path.join(ROOT, "build", "app", "liggghts-membrane")
GENERATOR = os.path.join(ROOT, "scripts", "generate_sample.py")

from liggghts_membrane import params
from liggghts_membrane.readers import key_value_lines, read_output, read_params

_LOCK = threading.Lock()
_LOOP = re.compile(r"Loop time of ([-+.\deE]+) on (\d+) procs for (\d+) steps")
_SPLIT = re.compile(r"(Pair|Neigh|Comm|Outpt|Other)\s+time \(%\) = \S+ \(([-+.\deE]+)\)")


# ----------------------------------------------------------------------------- small helpers
def log(msg):
    with _LOCK:
        print(msg, flush=True)


def tag(x):
    return f"{x:g}"


def sci(x):
    """A number as the input scripts write it: 8.45e7, 1e-4, 1e5."""
    mantissa, exponent = f"{x:e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


def floats(text):
    return [float(w) for w in text.split(",") if w.strip()]


def ints(text):
    return [int(w) for w in text.split(",") if w.strip()]


def sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:12]


def sha_text(text):
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def fmt(x, spec="{:.3g}", scale=1.0):
    """A number for a table: '' stays '', a non-finite one is '—'."""
    if x == "" or x is None:
        return ""
    try:
        x = float(x)
    except (TypeError, ValueError):
        return str(x)
    return "—" if x != x or x in (float("inf"), float("-inf")) else spec.format(x * scale)


def script_parameters(name):
    """The variables of an input script of examples/biaxial (or a path), includes followed."""
    return params.read_variables(name if os.path.isabs(name) else os.path.join(EXAMPLES, name))


def script_number(name, variable):
    return params.number(script_parameters(name), variable)


# ----------------------------------------------------------------------------- processes
def mpi_command(np_, mpirun="mpirun"):
    """The launcher prefix of an np_-rank run."""
    return [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)]


def run_command(cmd, cwd, screen, timeout):
    """(return code or 'timeout', wall [s], CPU time user+sys [s]) of one process, its
    output to `screen`; the CPU time is that of the process and its children (mpirun's
    ranks), robust when others load the machine."""
    t0 = time.time()
    with open(screen, "w") as f:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT,
                             env=dict(os.environ, OMP_NUM_THREADS="1"))
        timed_out = []
        timer = threading.Timer(timeout, lambda: (timed_out.append(1), p.kill()))
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)
        timer.cancel()
        p.returncode = rc = os.waitstatus_to_exitcode(status)
    return ("timeout" if timed_out else rc), time.time() - t0, ru.ru_utime + ru.ru_stime


def freeze_executable(exe, folder, report_only):
    """Copy the executable into the sweep's folder (a rebuild by someone else does not
    change it in the middle of a sweep): (path of the copy, its sha256 or '?')."""
    copy = os.path.join(folder, "liggghts-membrane")
    if not report_only:
        shutil.copy2(exe, copy + ".new")
        os.replace(copy + ".new", copy)
    return copy, (sha(copy) if os.path.exists(copy) else "?")


def script_set(src):
    """An input script and the files LIGGGHTS may include with it: every *.inc of its
    folder (an include is relative to the working directory, and some are named by a
    variable: include ${extra})."""
    folder = os.path.dirname(os.path.abspath(src))
    return [os.path.abspath(src)] + sorted(os.path.join(folder, f) for f in os.listdir(folder)
                                           if f.endswith(".inc"))


def freeze_script(src, folder):
    """Copy an input script and its includes (script_set) into folder/NAME.HASH/, HASH
    over all of them: (path of the script's copy, HASH). Runs made with another version
    of a script or of an include are re-run, never mixed; a run uses the copy's folder
    as its working directory (where LIGGGHTS finds the includes)."""
    files = script_set(src)
    h = sha_text("".join(os.path.basename(f) + "\0" + _text(f) for f in files))
    target = os.path.join(folder, f"{os.path.basename(src)}.{h}")
    if not os.path.exists(os.path.join(target, os.path.basename(src))):
        os.makedirs(target + ".new", exist_ok=True)
        for f in files:
            shutil.copy2(f, target + ".new")
        os.replace(target + ".new", target)
    return os.path.join(target, os.path.basename(src)), h


def generate_sample(scale, seed, data):
    """scripts/generate_sample.py --scale --seed --out data (quiet)."""
    subprocess.run(["/usr/bin/python3", GENERATOR, "--scale", repr(scale), "--seed", str(seed),
                    "--out", data], check=True, stdout=subprocess.DEVNULL)


# ----------------------------------------------------------------------------- a run's files
def _text(path):
    with open(path, errors="replace") as f:
        return f.read()


def loop_times(logfile):
    """(sum of Loop times [s], sum of steps) over the log's runs."""
    tsum, nsum = 0.0, 0
    if os.path.exists(logfile):
        for line in _text(logfile).splitlines():
            m = _LOOP.match(line)
            if m:
                tsum += float(m.group(1))
                nsum += int(m.group(3))
    return tsum, nsum


def time_split(logfile):
    """Percent of the longest run's loop time in LIGGGHTS' categories (Pair, Neigh,
    Comm, Outpt, Other; fixes such as the moving meshes and fix membrane2d are in
    Other), or {} when the log is missing."""
    best, split, current = -1, {}, None
    if not os.path.exists(logfile):
        return {}
    for line in _text(logfile).splitlines():
        m = _LOOP.match(line)
        if m:
            steps = int(m.group(3))
            current = {} if steps > best else None
            if current is not None:
                best = steps
            continue
        m = _SPLIT.match(line)
        if m and current is not None:
            current[m.group(1)] = float(m.group(2))
            split = current
    return split


def symptom(screen):
    """The first ERROR line, else the first 'Lost atoms' or nan line, else the last
    non-empty line of a screen output."""
    lines = [l.strip() for l in _text(screen).splitlines()] if os.path.exists(screen) else []
    for l in lines:
        if "ERROR" in l:
            return l[:200]
    for l in lines:
        if "Lost atoms" in l or "nan" in l.lower().split():
            return l[:200]
    nonempty = [l for l in lines if l]
    return nonempty[-1][:200] if nonempty else "no output"


def messages(screen, benign=()):
    """(first ERROR line, deduplicated WARNING lines without those holding a benign text)."""
    err, warns = "", []
    if os.path.exists(screen):
        for line in _text(screen).splitlines():
            s = line.strip()
            if not err and "ERROR" in s:
                err = s[:600]
            elif s.startswith("WARNING") and not any(b in s for b in benign) \
                    and s[:600] not in warns:
                warns.append(s[:600])
    return err, warns


def done_counts(text):
    """The counts of fix membrane2d at the end of a shear or pressure run: the last
    'membrane_counts key=value ...' line the input script prints (in.shear_membrane:
    escaped, chain_failures, detections, chain_changes -- per side, how often a
    detection changed the chain, what skipping it would risk; in.stability_pressure:
    escaped, chain_failures, widenings); {} without one (a rigid run)."""
    lines = key_value_lines(text, "membrane_counts")
    return lines[-1] if lines else {}


# ----------------------------------------------------------------------------- the run cache
def cached_meta(metafile, params_, done_status, retry_failed):
    """The meta.json of an earlier run with the same parameters, or None: a run that
    ended in done_status is reused, a failed one too unless retry_failed."""
    if not os.path.exists(metafile):
        return None
    meta = read_context(metafile)
    if meta.get("params") == params_ and (meta["status"] == done_status or not retry_failed):
        return meta
    return None


def known_meta(directory, params_, done_status, retry_failed, report_only, **not_run):
    """What is known of a run without running it: its cached meta.json, or with
    report_only a 'not run' placeholder (with the extra fields not_run), else None
    (the caller runs it)."""
    meta = cached_meta(os.path.join(directory, "meta.json"), params_, done_status, retry_failed)
    if meta is None and report_only:
        meta = dict(params=params_, status="not run", symptom="not run", **not_run)
    return meta


def empty_folder(folder):
    os.makedirs(folder, exist_ok=True)
    for f in os.listdir(folder):
        os.remove(os.path.join(folder, f))


def record_invocation(inv_file, entry):
    """Append one invocation (what it ran) to the sweep's invocations.json; returns all."""
    invocations = load_invocations(inv_file)
    invocations.append(entry)
    write_context(inv_file, invocations)
    return invocations


def load_invocations(inv_file):
    return read_context(inv_file) if os.path.exists(inv_file) else []


def started(t_start):
    return time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(t_start))


def sweep_main(argv, parse_args, report, sweep):
    """The command line of a sweep: with --from-csv the report again from PREFIX.csv
    and PREFIX.json (report(prefix)); otherwise sweep(args, start time) plans, runs and
    collects, and returns the report (finish_sweep). The report is printed."""
    args = parse_args(argv)
    args.argv = argv
    print(report(args.prefix) if args.from_csv else sweep(args, time.time()))
    return 0


def finish_sweep(runs, inv_file, t_start, entry, collect, prefix, csv_keys, report):
    """The end of a sweep's run step: record the invocation when it executed runs
    (entry(names of the runs executed): what else to record), collect the rows and the
    context (collect(invocations, minutes of this invocation or None)), write
    PREFIX.csv and PREFIX.json and make the report from them (report(prefix))."""
    executed = [r.name for r in runs if r.meta.get("executed_now")]
    invocations = load_invocations(inv_file)
    if executed:
        invocations = record_invocation(inv_file, dict(start=started(t_start), wall_s=time.time() - t_start,
                                                       **entry(executed)))
    rows, ctx = collect(invocations, (time.time() - t_start) / 60 if executed else None)
    write_rows(prefix + ".csv", rows, csv_keys)
    write_context(prefix + ".json", ctx)
    return report(prefix)


# ----------------------------------------------------------------------------- report inputs
def write_rows(path, rows, keys):
    """The CSV of a sweep: the keys as columns, floats with 6 significant digits."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, keys, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def _cell(text, as_int):
    if text == "" or not isinstance(text, str):
        return text
    try:
        return int(text) if as_int else float(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


def read_rows(path, int_keys=(), text_keys=()):
    """The rows of a CSV written by write_rows: '' stays '', the int_keys become ints,
    the text_keys stay text, every other cell that is a number becomes a float."""
    with open(path, newline="") as f:
        return [{k: (v if k in text_keys else _cell(v, k in int_keys)) for k, v in r.items()}
                for r in csv.DictReader(f)]


def write_context(path, context):
    with open(path, "w") as f:
        json.dump(context, f, indent=1)
        f.write("\n")


def read_context(path):
    with open(path) as f:
        return json.load(f)


def markdown_table(rows, cols):
    """Markdown table of rows with (title, function of row) columns."""
    out = ["| " + " | ".join(c for c, _ in cols) + " |", "|" + "---|" * len(cols)]
    for r in rows:
        out.append("| " + " | ".join(str(f(r)).replace("|", "/") for _, f in cols) + " |")
    return "\n".join(out)


# ----------------------------------------------------------------------------- kept runs
# The small benchmarks (damping_bias, density_scaling, f0_origin, porosity_coordination)
# run the example scripts from examples/biaxial, each run kept in a folder and reused
# when it finished (its screen output has the script's final line).
def kept_run(args, screen, done_marker, np_):
    """Run the executable with `args` in examples/biaxial unless `screen` already holds
    `done_marker`; return the screen text."""
    if os.path.exists(screen) and done_marker in _text(screen):
        return _text(screen)
    cmd = mpi_command(np_) + [EXE] + args + ["-log", "none"]
    with open(screen + ".tmp", "w") as f:
        p = subprocess.run(cmd, cwd=EXAMPLES, stdout=f, stderr=subprocess.STDOUT)
    text = _text(screen + ".tmp")
    if p.returncode != 0 or done_marker not in text:
        raise RuntimeError("%s failed: see %s" % (" ".join(args[:2]), os.path.relpath(screen + ".tmp", ROOT)))
    os.replace(screen + ".tmp", screen)
    return text


def var_args(settings):
    """-var NAME VALUE ... of a dict."""
    out = []
    for key, value in settings.items():
        out += ["-var", key, str(value)]
    return out


def prepare(scale, seed, folder, settings=None, np_=1):
    """Generate and prepare one sample in `folder` (kept); returns its restart file."""
    os.makedirs(folder, exist_ok=True)
    data = os.path.join(folder, "sample.data")
    restart = os.path.join(folder, "prepared.restart")
    if not os.path.exists(data):
        generate_sample(scale, seed, data)
    kept_run(["-in", "in.prepare", "-var", "data", data, "-var", "out", restart] + var_args(settings or {}),
             os.path.join(folder, "screen.prepare"), "PREPARED porosity", np_)
    return restart


class Shear:
    """One finished shear: its OUT table, its screen text and the numbers the scripts print."""

    def __init__(self, out, text):
        self.table = read_output(out)
        self.text = text
        params = read_params(out + ".params")      # what shear_loading.inc prints there
        self.nramp = int(params["nramp"])
        self.atoms = int(params["atoms"])

    def after_ramp(self):
        """Mask of the OUT rows after the platen speed ramp."""
        step = self.table["step"]
        return step >= step[0] + self.nramp


def shear(case, restart, out, settings=None, np_=1):
    """Shear `restart` with in.shear_<case> (rigid or membrane), OUT table `out` (kept)."""
    args = ["-in", "in.shear_" + case, "-var", "restart", restart, "-var", "out", out] + var_args(settings or {})
    return Shear(out, kept_run(args, out + ".screen", "SHEAR done", np_))
