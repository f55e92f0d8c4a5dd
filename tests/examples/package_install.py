#!/usr/bin/python3
"""The Debian package (packaging/CMakeLists.txt, doc/install.md), built by cpack from
this build and installed into a temporary root with dpkg -x, runs the small example
from its installed paths:

- its Depends name what the executable links (libliggghts3, the Open MPI library)
  and what the scripts run (liggghts, openmpi-bin, python3-numpy, python3-matplotlib),
  and apt resolves them on this machine with nothing else to install (--reinstall:
  the same answer when the package is installed here already);
- the installed executable finds every library it links;
- liggghts-membrane-sample writes a sample; in.prepare and in.shear_membrane run with
  the installed executable in the installed examples folder, finding their includes
  and meshes there (no -var meshdir), and write only where -var out points;
- liggghts-membrane-report reports the run: its last s1/s3 and axial strain are those
  of the table as this test reads it; --help names the command;
- the installed commands use the installed Python package
  (usr/lib/python3/dist-packages/liggghts_membrane, without bench/ and the test
  helpers), not the checkout's (PYTHONPATH, which CTest sets, is cleared here);
- nothing is written into the installed tree (the examples and scripts can live in a
  read-only /usr/share).

    package_install.py CPACK_CONFIG
"""
import csv
import os
import subprocess
import sys
import tempfile

from example_run import Checks, run, table

SHARE = os.path.join("usr", "share", "liggghts-membrane")


def tree_state(root):
    """(path, size, mtime) of every file below root."""
    return sorted((os.path.relpath(os.path.join(d, n), root), os.path.getsize(os.path.join(d, n)),
                   os.path.getmtime(os.path.join(d, n)))
                  for d, _, names in os.walk(root) for n in names)


def main():
    config = sys.argv[1]
    os.environ.pop("PYTHONPATH", None)   # the installed package only, not the checkout's
    check = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run(["cpack", "-G", "DEB", "--config", config, "-B", os.path.join(tmp, "pkg")],
                           capture_output=True, text=True)
        debs = [os.path.join(tmp, "pkg", n) for n in os.listdir(os.path.join(tmp, "pkg")) if n.endswith(".deb")]
        if p.returncode != 0 or len(debs) != 1:
            sys.exit("FAIL: cpack -G DEB exited %d with %s\n%s" % (p.returncode, debs, (p.stdout + p.stderr)[-3000:]))
        deb = debs[0]
        depends = subprocess.run(["dpkg-deb", "-f", deb, "Depends"], capture_output=True, text=True).stdout
        names = {d.split()[0] for d in depends.replace("|", ",").split(",") if d.strip()}
        wanted = {"liggghts", "libliggghts3", "libopenmpi3", "openmpi-bin", "python3", "python3-numpy",
                  "python3-matplotlib"}
        check(wanted <= names, "Depends: %s (lacks %s)" % (depends.strip(), " ".join(sorted(wanted - names)) or "none"))
        p = subprocess.run(["apt-get", "install", "--simulate", "--reinstall", "--no-install-recommends", deb],
                           capture_output=True, text=True)
        inst = [l.split()[1] for l in p.stdout.splitlines() if l.startswith("Inst ")]
        check(p.returncode == 0 and inst == ["liggghts-membrane"],
              "apt resolves the package's dependencies here, installing only it (%s)"
              % (" ".join(inst) or (p.stdout + p.stderr)[-300:].strip()))

        root, work = os.path.join(tmp, "root"), os.path.join(tmp, "work")
        os.makedirs(work)
        subprocess.run(["dpkg", "-x", deb, root], check=True)
        exe = os.path.join(root, "usr", "bin", "liggghts-membrane")
        example = os.path.join(root, SHARE, "examples", "biaxial")
        ldd = subprocess.run(["ldd", exe], capture_output=True, text=True).stdout
        check("liggghts" in ldd and "not found" not in ldd, "the installed executable finds its libraries")
        package = os.path.join(root, "usr", "lib", "python3", "dist-packages", "liggghts_membrane")
        check(os.path.isfile(os.path.join(package, "report_command.py"))
              and not os.path.exists(os.path.join(package, "bench"))
              and not os.path.exists(os.path.join(package, "synthetic.py")),
              "the package is installed in usr/lib/python3/dist-packages (without bench/, synthetic.py)")
        before = tree_state(root)

        helped = subprocess.run([os.path.join(root, "usr", "bin", "liggghts-membrane-report"), "--help"],
                                capture_output=True, text=True)
        check(helped.returncode == 0 and "usage: liggghts-membrane-report" in helped.stdout,
              "liggghts-membrane-report --help")
        data, restart = os.path.join(work, "sample.data"), os.path.join(work, "prepared.restart")
        run([os.path.join(root, "usr", "bin", "liggghts-membrane-sample"), "--scale", "0.15", "--seed", "7",
             "--out", data], os.path.join(work, "sample.log"), cwd=work)
        mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "1", exe]
        out = run(mpi + ["-in", "in.prepare", "-var", "data", data, "-var", "out", restart, "-log", "none"],
                  os.path.join(work, "prepare.log"), cwd=example)
        check(out.count("PREPARED porosity") == 1, "in.prepare ran from the installed examples folder")
        shear = os.path.join(work, "shear_membrane.txt")
        out = run(mpi + ["-in", "in.shear_membrane", "-var", "restart", restart, "-var", "out", shear,
                         "-var", "eatarget", "0.004", "-var", "ndump", "400", "-log", "none"],
                  os.path.join(work, "shear.log"), cwd=example)
        check("SHEAR done" in out, "in.shear_membrane ran from the installed examples folder")

        report = os.path.join(work, "report")
        run([os.path.join(root, "usr", "bin", "liggghts-membrane-report"), shear, "--outdir", report],
            os.path.join(work, "report.log"), cwd=work)
        with open(os.path.join(report, "summary.csv")) as f:
            cells = {r[0]: r[1:] for r in csv.reader(f)}
        t = table(shear)
        last = [float(cells["s1/s3 at the end"][0]), float(cells["eps_11 at the end [%]"][0])]
        check(cells["quantity"] == ["shear_membrane"] and abs(last[0] - t["s1/s3"][-1]) < 1e-4
              and abs(last[1] - 100 * t["ea"][-1]) < 1e-3,
              "the report: s1/s3 %.4f at eps_11 %.3f %% at the end, as the table's last line (%.4f, %.3f %%)"
              % (last[0], last[1], t["s1/s3"][-1], 100 * t["ea"][-1]))
        check(all(os.path.getsize(os.path.join(report, n)) > 10000 for n in ("stress_strain.png", "fabric.png")),
              "the report drew its figures")
        after = tree_state(root)
        changed = sorted(set(after) ^ set(before))
        check(not changed, "nothing written into the installed tree (%s)" % (changed[:3] or "none"))
    if check.failures:
        sys.exit("FAIL: %d check(s)" % len(check.failures))
    print("all checks passed")


if __name__ == "__main__":
    main()
