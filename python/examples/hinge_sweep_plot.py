"""A sweep of circular notch hinges (Al 7075, w = h = 10 mm, 20 mm blank): the compliant-axis
stiffness k_bend and the rotation at the allowable stress over the notch radius R for five
thicknesses t, plotted with matplotlib into hinge_sweep.png (the folder given, else the
working folder).

Run: python python/examples/hinge_sweep_plot.py [OUT_DIR]
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import flexfem  # noqa: E402

BASE = {
    "analysis": "hinge",
    "material": "Al7075",
    "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20},
}
VARY = {"hinge.t": [1, 1.5, 2, 2.5, 3], "hinge.R": {"from": 2, "to": 12, "steps": 21}}


def main(out_dir: Path = Path(".")) -> Path:
    rows = flexfem.sweep(BASE, vary=VARY, fields=["k_bend", "max_rotation_deg"]).rows()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for t in VARY["hinge.t"]:
        mine = [r for r in rows if r["params"]["hinge.t"] == t]
        r_mm = [r["params"]["hinge.R"] for r in mine]
        ax1.plot(r_mm, [r["result"]["k_bend"] / 1e3 for r in mine], label=f"t = {t} mm")
        ax2.plot(r_mm, [r["result"]["max_rotation_deg"] for r in mine], label=f"t = {t} mm")
    ax1.set(xlabel="notch radius R, mm", ylabel="k_bend, N·m/rad", yscale="log")
    ax2.set(xlabel="notch radius R, mm", ylabel="rotation at allowable stress, °")
    ax1.legend()
    fig.suptitle("Circular notch hinges, Al 7075 (flexfem.sweep)")
    fig.tight_layout()
    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / "hinge_sweep.png"
    fig.savefig(path, dpi=100)
    # Thicker notch: stiffer; bigger radius: softer and more rotation before yield.
    first = [r["result"]["k_bend"] for r in rows if r["params"]["hinge.R"] == 2]
    assert len(rows) == 105 and all(a < b for a, b in zip(first, first[1:]))  # zip-checked: one list
    print(f"{len(rows)} hinges; wrote {path}")
    return path


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("."))
