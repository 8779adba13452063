"""cmake --install (issue 9, item 7): installs into a temporary prefix, then runs the installed
binary (2 ranks) on an installed example scene whose mesh path is relative (runs/sail.yaml reads
../meshes/sail.msh) and an installed script on its result.
Checks: bin/sinew, share/sinew/scripts/*.py (executable), share/sinew/runs, share/sinew/meshes,
share/doc/sinew (README.md, docs); the installed run converges from another working directory; the
Python package in lib/python3/dist-packages reads the result and runs a scene with the installed
binary (issue 25)."""
import os
import shutil
import subprocess
import tempfile

import sinewtest as st

build = os.path.dirname(st.BIN)
prefix = tempfile.mkdtemp(prefix="sinew_install_")
try:
    p = subprocess.run(["cmake", "--install", build, "--prefix", prefix], capture_output=True, text=True, timeout=300)
    st.check(p.returncode == 0, f"cmake --install exit {p.returncode}: {p.stderr[-2000:]}")
    binary = os.path.join(prefix, "bin", "sinew")
    share = os.path.join(prefix, "share", "sinew")
    doc = os.path.join(prefix, "share", "doc", "sinew")
    st.check(os.access(binary, os.X_OK), "bin/sinew installed and executable")
    for rel in ("scripts/plot_results.py", "scripts/plot_input.py", "scripts/plot_sensors.py", "scripts/h5check.py",
                "runs/sail.yaml", "runs/crosshinge.yaml", "meshes/sail.msh"):
        st.check(os.path.exists(os.path.join(share, rel)), f"share/sinew/{rel} installed")
    st.check(os.access(os.path.join(share, "scripts", "plot_results.py"), os.X_OK), "installed scripts are executable")
    for rel in ("README.md", "scene.md", "results.md", "accuracy_beam.md", "accuracy_beam.png"):
        st.check(os.path.exists(os.path.join(doc, rel)), f"share/doc/sinew/{rel} installed")
    st.check(not os.path.exists(os.path.join(share, "scripts", "run")), "source-tree scripts (run, setup) not installed")

    # the installed binary on an installed scene, from an unrelated working directory
    work = tempfile.mkdtemp(prefix="sinew_install_run_")
    out = os.path.join(work, "sail.h5")
    p = subprocess.run([st.MPIEXEC, "-n", "2", binary, os.path.join(share, "runs", "sail.yaml"), "-o", out],
                       cwd=work, env=st.ENV, capture_output=True, text=True, timeout=600)
    print("\n".join("    " + l for l in p.stdout.splitlines()[:4]))
    st.check(p.returncode == 0, f"installed sinew on share/sinew/runs/sail.yaml: exit {p.returncode}\n{p.stdout[-2000:]}")
    if p.returncode == 0:
        with st.h5(out) as f:
            st.check(int(f.attrs["converged"]) == 1 and f["node/p"].shape[0] > 1, "installed run converged, steps written")
        q = subprocess.run(["/usr/bin/python3", os.path.join(share, "scripts", "plot_results.py"), out], cwd=work,
                           capture_output=True, text=True, timeout=300)
        print("    " + q.stdout.strip().replace("\n", "\n    "))
        png = next((l[6:] for l in q.stdout.splitlines() if l.startswith("wrote ")), "")
        st.check(q.returncode == 0 and png.endswith(".png") and os.path.getsize(png) > 5000,
                 f"installed plot_results.py draws the result: {q.stderr[-1000:]}")
        st.check("deformed (coloured by membrane stress and cable force) and found shape (grey)" in q.stdout,
                 "after form finding the wind load deforms the found shape (the reference drawn in grey)")
        # the installed Python package finds the installed binary (no SINEW_BIN) and reads the result
        site = os.path.join(prefix, "lib", "python3", "dist-packages")
        st.check(os.path.exists(os.path.join(site, "sinew", "__init__.py")), "lib/python3/dist-packages/sinew installed")
        env = {k: v for k, v in st.ENV.items() if k != "SINEW_BIN"}
        env["PYTHONPATH"] = site
        code = ("import sinew; out = sinew.load(%r); print(out.ns, len(out.node)); "
                "sim = sinew.Scene.from_yaml(%r); sim.opt['loadsteps'] = 2; print(sim.run().ns)") % (
            out, os.path.join(share, "runs", "crosshinge.yaml"))
        q = subprocess.run(["/usr/bin/python3", "-c", code], cwd=work, env=env, capture_output=True, text=True, timeout=300)
        print("    python: " + q.stdout.strip().replace("\n", "; "))
        st.check(q.returncode == 0 and q.stdout.split()[-1:] == ["2"],
                 f"installed Python package: load a result, run a scene with the installed binary: {q.stderr[-1500:]}")
        st.check(os.access(os.path.join(share, "scripts", "spacar2sinew.py"), os.X_OK), "spacar2sinew.py installed")
        # installed plot_input.py on an installed scene finds the installed bin/sinew (no SINEW_BIN)
        env = {k: v for k, v in os.environ.items() if k != "SINEW_BIN"}
        scene = os.path.join(work, "crosshinge.yaml")
        shutil.copy(os.path.join(share, "runs", "crosshinge.yaml"), scene)
        q = subprocess.run(["/usr/bin/python3", os.path.join(share, "scripts", "plot_input.py"), scene], cwd=work,
                           env=env, capture_output=True, text=True, timeout=300)
        print("    " + q.stdout.strip().replace("\n", "\n    "))
        st.check(q.returncode == 0 and f"input check: {binary} " in q.stdout
                 and os.path.exists(os.path.join(work, "crosshinge_input.png")),
                 f"installed plot_input.py draws a scene with the installed sinew: {q.stderr[-500:]}")
    shutil.rmtree(work, ignore_errors=True)
finally:
    shutil.rmtree(prefix, ignore_errors=True)
st.done()
