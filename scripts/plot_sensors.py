#!/usr/bin/python3
"""Time (or load-factor) plots of every /sensors/<name> dataset of a Sinew result file, one panel per
sensor, its components and units named (the sensor's Exudyn output variable comes from the scene
stored in the file).
usage: scripts/plot_sensors.py result.h5 [-o out.png]
The picture goes beside the result file as <result>_sensors.png unless -o names it."""
import argparse
import os
import sys

import yaml

from plot_results import load_matplotlib, open_result

# Exudyn output variable -> (component names, unit); vectors are global x, y, z unless "Local"
VARIABLES = {
    "Position": (("x", "y", "z"), "m"),
    "Displacement": (("ux", "uy", "uz"), "m"),
    "Velocity": (("vx", "vy", "vz"), "m/s"),
    "VelocityLocal": (("v_axial", "v_normal", "v_z"), "m/s"),
    "Acceleration": (("ax", "ay", "az"), "m/s^2"),
    "Director1": (("r'_x", "r'_y", "r'_z"), "-"),
    "AngularVelocity": (("omega_x", "omega_y", "omega_z"), "rad/s"),
    "AngularAcceleration": (("alpha_x", "alpha_y", "alpha_z"), "rad/s^2"),
    "Rotation": (("phi",), "rad"),
    "StrainLocal": (("axial strain",), "-"),
    "CurvatureLocal": (("curvature",), "1/m"),
    "ForceLocal": (("axial force",), "N"),
    "TorqueLocal": (("bending moment",), "N m"),
}
# the same variables with 3 components: beam node and beam element sensors (local frame for *Local)
VARIABLES3 = {
    "Rotation": (("rx", "ry", "rz"), "rad"),
    "ForceLocal": (("N", "Qy", "Qz"), "N"),
    "TorqueLocal": (("T", "My", "Mz"), "N m"),
}


def sensor_variables(f):
    """Sensor name -> Exudyn variable, from the scene text stored in the result file."""
    scene = f.attrs.get("scene", "")
    scene = scene.decode("utf-8", "replace") if isinstance(scene, bytes) else str(scene)
    try:
        sensors = (yaml.safe_load(scene) or {}).get("sensors") or []
    except yaml.YAMLError:
        return {}
    return {str(s.get("name")): str(s.get("variable")) for s in sensors if isinstance(s, dict)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="PNG file (default: <result>_sensors.png beside the result file)")
    a = ap.parse_args()
    out = a.output or os.path.splitext(a.h5)[0] + "_sensors.png"
    with open_result(a.h5) as f:
        if "sensors" not in f:
            sys.exit(f"{a.h5}: no /sensors group (the scene has no sensors)")
        if "time" not in f and "load_factor" not in f:
            sys.exit(f"{a.h5}: no /time or /load_factor (no step written)")
        xname = "time" if "time" in f else "load_factor"
        x = f[xname][:]
        variables = sensor_variables(f)
        names = sorted(f["sensors"].keys())
        plt = load_matplotlib()  # after the input was read: bad files fail fast
        fig, axes = plt.subplots(len(names), 1, figsize=(7, 2.6 * len(names)), squeeze=False, sharex=True)
        for ax, name in zip(axes[:, 0], names):
            v = f["sensors/" + name][:]
            v = v.reshape(len(x), -1)
            var = variables.get(name, "")
            comps, unit = VARIABLES.get(var, (tuple(f"[{k}]" for k in range(v.shape[1])), "?"))
            if v.shape[1] == 3 and var in VARIABLES3:
                comps, unit = VARIABLES3[var]
            for k in range(v.shape[1]):
                if v.shape[1] == 1 or abs(v[:, k]).max() > 0:
                    comp = comps[k] if k < len(comps) else f"[{k}]"
                    ax.plot(x, v[:, k], label=f"{name}: {comp} [{unit}]")
            ylabel = f"{name}: {var or 'value'} [{unit}]"
            ax.set_ylabel(ylabel)
            print(f"panel: {ylabel}; components: {', '.join(l.get_label() for l in ax.get_lines())}")
            ax.legend(loc="best", fontsize=8)
            ax.grid(True, alpha=0.3)
        xlabel = "time [s]" if xname == "time" else "load factor [-]"
        axes[-1, 0].set_xlabel(xlabel)
        print(f"x axis: {xlabel}")
        fig.tight_layout()
        fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
