"""The 3-PRS compliant stage's frequency response (cases/ruiz2019_stage_frf.json: actuator 1
force → platform pose) as a state-space model handed to python-control (scipy.signal when
python-control is not installed), closed by an integral controller on the platform's z
displacement; prints the loop's crossover frequency and margins.

The plant G(s) = C (sI − A)⁻¹ B + D comes from flexfem.state_space (numpy arrays over the
solver's buffers); an integral controller K(s) = k_i / s gives a loop L = K G that crosses over
at f_c = 20 Hz, below the first mode, so the gain margin is set by the first resonance.

Run: python python/examples/stage_loop_shape.py
"""

from pathlib import Path

import numpy as np

import flexfem

ROOT = Path(__file__).resolve().parents[2]
CROSSOVER_HZ = 20.0


def main() -> dict:
    ss = flexfem.state_space(ROOT / "cases" / "ruiz2019_stage_frf.json")
    a, b, c, d = ss["A"], ss["B"], ss["C"], ss["D"]
    z = 2  # outputs: platform x, y, z (mm), rx, ry, rz (degrees)
    cz, dz = c[z : z + 1, :], d[z : z + 1, :]
    wc = 2 * np.pi * CROSSOVER_HZ

    def plant(w: np.ndarray) -> np.ndarray:
        """G_z(iω), mm/N."""
        n = a.shape[0]
        return np.array([(cz @ np.linalg.solve(1j * x * np.eye(n) - a, b) + dz)[0, 0] for x in w])

    g0 = (dz - cz @ np.linalg.solve(a, b))[0, 0]  # static gain, mm/N
    # |K G| = 1 at the crossover; the sign of G(0) keeps the feedback negative.
    ki = np.sign(g0) * wc / abs(plant(np.array([wc]))[0])
    try:
        import control

        g = control.ss(a, b, cz, dz)
        loop = control.tf([ki], [1, 0]) * g
        gm, pm, wg, wp = control.margin(loop)
        tool = "python-control"
    except ImportError:  # scipy.signal: margins read off a dense frequency grid
        w = np.logspace(0, 4.5, 20000)
        loop_w = ki / (1j * w) * plant(w)
        mag, ph = np.abs(loop_w), np.unwrap(np.angle(loop_w))
        i_c = np.argmin(np.abs(mag - 1))
        pm, wp = 180 + np.degrees(ph[i_c]), w[i_c]
        i_g = np.argmin(np.abs(ph + np.pi))
        gm, wg = 1 / mag[i_g], w[i_g]
        tool = "scipy"
    f1 = ss["omega"][0] / (2 * np.pi)
    print(f"plant: {a.shape[0]} states, first mode {f1:.1f} Hz, static gain {g0:.4e} mm/N")
    print(f"integral gain k_i = {ki:.4e} N/(mm·s) ({tool})")
    print(f"crossover {wp / (2 * np.pi):.2f} Hz, phase margin {pm:.1f}°, gain margin {20 * np.log10(gm):.1f} dB at {wg / (2 * np.pi):.1f} Hz")
    assert abs(wp / (2 * np.pi) - CROSSOVER_HZ) < 0.05 * CROSSOVER_HZ
    assert pm > 60 and gm > 1
    return {"crossover_hz": wp / (2 * np.pi), "phase_margin_deg": pm, "gain_margin": gm}


if __name__ == "__main__":
    main()
