"""The 3-PRS compliant stage's frequency response (cases/ruiz2019_stage_frf.json: actuator 1
force → platform pose) as a state-space model handed to python-control, for the loop shape of
a z-position controller.

The plant G(s) = C (sI − A)⁻¹ B + D (mm/N) comes from flexfem.state_space (numpy arrays over the
solver's buffers). Its first mode (79 Hz, ζ ≈ 1.3 %) peaks about 20 dB above the static gain, so
an integral controller K = k_i/s tuned for a 6 dB gain margin crosses over near 1 Hz; a notch
at that mode, N(s) = (s² + 2 ζ₁ ω₁ s + ω₁²)/(s² + 2·0.7 ω₁ s + ω₁²), lets the same margin hold
at a crossover many times higher.

Run: python python/examples/stage_loop_shape.py
"""

from pathlib import Path

import numpy as np

import flexfem

ROOT = Path(__file__).resolve().parents[2]
GAIN_MARGIN = 2.0  # 6 dB


def main() -> dict:
    ss = flexfem.state_space(ROOT / "cases" / "ruiz2019_stage_frf.json")
    a, b, c, d = ss["A"], ss["B"], ss["C"], ss["D"]
    z = 2  # outputs: platform x, y, z (mm), rx, ry, rz (degrees)
    cz, dz = c[z : z + 1, :], d[z : z + 1, :]
    g0 = (dz - cz @ np.linalg.solve(a, b))[0, 0]  # static gain, mm/N
    w1, z1 = ss["omega"][0], ss["zeta"][0]
    notch = ([1, 2 * z1 * w1, w1**2], [1, 2 * 0.7 * w1, w1**2])
    import control

    plant = control.ss(a, b, cz, dz)

    def margins(shape):
        """(gain margin, phase margin °, crossover Hz) of k_i/s · shape · G with k_i set for
        GAIN_MARGIN."""
        unit = control.tf([np.sign(g0)], [1, 0]) * shape * plant
        # python-control evaluates the transfer function's polynomials far above the modes.
        with np.errstate(over="ignore", invalid="ignore"):
            gm1 = control.margin(unit)[0]
            gm, pm, _, wp = control.margin(gm1 / GAIN_MARGIN * unit)
        return gm, pm, wp / (2 * np.pi)

    plain = margins(control.tf([1], [1]))
    notched = margins(control.tf(*notch))
    tool = "python-control"
    print(f"plant: {a.shape[0]} states, first mode {w1 / (2 * np.pi):.1f} Hz (ζ = {z1:.4f}), static gain {g0:.4e} mm/N ({tool})")
    for name, (gm, pm, fc) in (("integral", plain), ("integral + notch", notched)):
        print(f"{name:>16}: crossover {fc:.2f} Hz, phase margin {pm:.1f}°, gain margin {20 * np.log10(gm):.1f} dB")
    assert abs(plain[0] - GAIN_MARGIN) < 1e-3 and abs(notched[0] - GAIN_MARGIN) < 1e-3
    # 6 dB and 30°: the usual least margins of a loop shape.
    assert notched[2] > 3 * plain[2] and notched[1] > 30
    return {"plain": plain, "notched": notched}


if __name__ == "__main__":
    main()
