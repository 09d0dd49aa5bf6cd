"""Size the notch thickness t of the parallelogram guide (meshes/parallelogram_parameters.json:
four circular notch hinges, Al 7075) for an actuation stiffness k_x = 2 N/mm along the motion,
with scipy.optimize.brentq over flexfem's static solve; then report the stroke at the allowable
stress and the out-of-plane stiffness k_z of that design.

Run: python python/examples/parallelogram_sizing.py
"""

from pathlib import Path

from scipy.optimize import brentq

import flexfem

ROOT = Path(__file__).resolve().parents[2]
TARGET_KX = 2.0  # N/mm


def metrics(t: float) -> dict:
    """k_x, k_z (N/mm) and the stroke at the allowable stress (mm) of the guide with notch t (mm)."""
    case = {
        "analysis": "static",
        "mesh": str(ROOT / "meshes" / "parallelogram_parameters.json"),
        "parameters": {"t": t},
        "load_cases": [{"name": "stroke_1mm", "displacements": [{"node": 8, "dof": "ux", "value": 1}]}],
        "metrics": [
            {"name": "k_x", "kind": "stiffness", "node": 8, "dof": "ux"},
            {"name": "k_z", "kind": "stiffness", "node": 8, "dof": "uz"},
            {"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "stroke_1mm"},
        ],
    }
    return flexfem.run(case)["metrics"]


def main() -> dict:
    calls = []

    def residual(t: float) -> float:
        calls.append(t)
        return metrics(t)["k_x"] - TARGET_KX

    t = brentq(residual, 0.5, 2.0, xtol=1e-6)
    m = metrics(t)
    print(f"notch thickness t = {t:.4f} mm ({len(calls)} solves)")
    print(f"k_x = {m['k_x']:.4f} N/mm, k_z = {m['k_z']:.1f} N/mm, stroke at allowable = {m['stroke']['stroke']:.3f} mm")
    assert abs(m["k_x"] - TARGET_KX) < 1e-4 * TARGET_KX
    return {"t": t, **m}


if __name__ == "__main__":
    main()
