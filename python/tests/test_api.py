"""The package's functions against the command line's output and against engineering
identities the result must satisfy (each test names its reference)."""

import json
import pickle
import threading
import time
from collections.abc import Mapping

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import flexfem
from conftest import CASES, ROOT, cli, cli_json, differences

HINGE = CASES / "ruiz2019_hinge_revolute.json"
FRF = CASES / "ruiz2019_stage_frf.json"
MODAL = CASES / "superelement_cantilever_modal.json"


def test_check_returns_the_kind_as_cli_does():
    code, out, err = cli("check", HINGE)
    assert code == 0 and out.startswith("ok: hinge case"), err
    assert flexfem.check(HINGE) == "hinge"
    assert flexfem.check(CASES / "ruiz2019_hinge_sweep.json") == "sweep"


def test_check_warns_as_cli_does():
    pantilt = CASES / "pantilt_8r.json"
    code, out, err = cli("check", pantilt)
    assert code == 0 and out.startswith("ok: static case"), err
    want = [line[len("warning: "):] for line in err.splitlines()]
    assert len(want) == 2 and "corner_filleted h/t = 25" in want[0], err
    with pytest.warns(UserWarning) as record:
        assert flexfem.check(pantilt) == "static"
    assert [str(r.message) for r in record] == want


def test_schema_equals_cli():
    want = cli_json("schema")
    got = flexfem.schema()
    assert got == want
    assert "hinge" in json.dumps(got["$defs"] if "$defs" in got else got)


def test_hinge_compliance_is_a_numpy_array_equal_to_cli():
    # The Ruiz et al. (2019) revolute hinge: R = 8, t = 2, w = h = 10, 20 mm blank, Al 7075.
    want = cli_json("run", HINGE)
    h = flexfem.hinge("circular_notch", "Al7075", R=8, t=2, w=10, h=10, blank_length=20)
    assert isinstance(h.compliance, np.ndarray)
    assert h.compliance.shape == (6, 6) and h.compliance.dtype == np.float64
    assert np.array_equal(h.compliance, np.array(want["compliance"]))
    assert differences(want, h.result) == []
    # Maxwell–Betti reciprocity: the compliance is symmetric (to rounding of the solve).
    c = h.compliance
    assert np.max(np.abs(c - c.T)) <= 1e-12 * np.max(np.abs(c))
    # k_bend is M_y/θ_y under a pure moment: 1/C[ry, ry].
    assert h.k_bend * c[4, 4] == pytest.approx(1.0, rel=1e-9)


def test_hinge_dimension_error_names_the_path():
    with pytest.raises(flexfem.CaseError) as e:
        flexfem.hinge("circular_notch", "Al7075", R=8, t=-2, w=10, h=10, blank_length=20)
    assert e.value.path == "hinge.t"


def test_matrices_equal_the_exported_matrix_market_files(tmp_path):
    out = tmp_path / "out"
    code, _, err = cli("run", MODAL, "--out", out, "--export-matrices")
    assert code == 0, err
    m = flexfem.matrices(MODAL)
    for name in ("K", "M"):
        want = scipy.sparse.csr_matrix(scipy.io.mmread(out / f"{name}.mtx"))
        got = m[name]
        assert scipy.sparse.issparse(got) and got.shape == want.shape
        # Matrix Market values are written to round-trip exactly.
        assert abs(got - want).max() == 0.0
    assert len(m["dofs"]) == m["K"].shape[0] == len(m["node_frame"])
    rows = (out / "dofs.csv").read_text().splitlines()[1:]
    assert len(rows) == len(m["dofs"])
    assert [tuple(r.split(",")[1:3]) for r in rows] == [(str(n), d) for n, d in m["dofs"]]


def test_matrices_give_the_modal_frequencies():
    # K φ = ω² M φ on the exported equations: the modal case's frequencies (1e-9 relative;
    # the README quotes 1e-12 for the eigenvalues with sprs and scipy's mmread + eigh).
    m = flexfem.matrices(MODAL)
    res = flexfem.run(MODAL)
    want = np.array([mode["frequency_hz"] for mode in res["modes"]])
    import scipy.linalg

    w2 = scipy.linalg.eigh(m["K"].toarray(), m["M"].toarray(), eigvals_only=True)
    got = np.sqrt(w2[: len(want)]) / (2 * np.pi)
    assert np.max(np.abs(got - want) / want) < 1e-9


def test_matrices_share_the_solver_buffer():
    # The values array is the Rust vector handed over (owned by numpy, not a copy of a list).
    k = flexfem.matrices(MODAL)["K"]
    assert k.data.flags["C_CONTIGUOUS"] and k.data.dtype == np.float64


@pytest.fixture(scope="module")
def frf_result():
    return flexfem.run(FRF)


def test_state_space_equals_the_frf_result(frf_result):
    ss = flexfem.state_space(FRF)
    want = frf_result["state_space"]
    for name in "ABCD":
        a = ss[name]
        assert isinstance(a, np.ndarray) and a.flags["F_CONTIGUOUS"]
        assert np.array_equal(a, np.array(want[name.lower()]).reshape(a.shape))
    # DC gain D − C A⁻¹ B equals the static compliance (Craig & Kurdila 2006, §11.4; the
    # README quotes 1e-16 for the Rust check).
    dc = ss["D"] - ss["C"] @ np.linalg.solve(ss["A"], ss["B"])
    gain = np.array(frf_result["static_gain"])
    assert np.max(np.abs(dc - gain)) <= 1e-10 * np.max(np.abs(gain))
    hz = np.array([m["frequency_hz"] for m in frf_result["modes"]])
    assert np.allclose(ss["omega"] / (2 * np.pi), hz, rtol=1e-12, atol=0)


def test_state_space_refuses_other_kinds():
    with pytest.raises(flexfem.CaseError) as e:
        flexfem.state_space(HINGE)
    assert e.value.path == "analysis"


def test_sweep_table_equals_cli_csv(tmp_path):
    sweep = CASES / "ruiz2019_hinge_sweep.json"
    csv = tmp_path / "t.csv"
    code, _, err = cli("sweep", sweep, "--csv", csv)
    assert code == 0, err
    s = flexfem.sweep(sweep)
    assert len(s) == 55 and s.axes == ["hinge.t", "hinge.R"]
    assert s.to_csv() == csv.read_text()
    pd = pytest.importorskip("pandas")
    df = s.to_pandas()
    want = pd.read_csv(csv)
    assert df.shape == (55, want.shape[1]) and list(df.columns) == list(want.columns)


def test_sweep_rows_are_mappings_over_the_cli_lines():
    # Each row reads as the JSON line `flexfem sweep` printed for that design: the same keys in
    # the same order, the same values (floats exactly: the line's text round-trips).
    code, out, err = cli("sweep", CASES / "ruiz2019_hinge_sweep.json")
    assert code == 0, err
    want = sorted((json.loads(line) for line in out.splitlines()), key=lambda r: r["index"])
    rows = flexfem.sweep(CASES / "ruiz2019_hinge_sweep.json").rows()
    assert len(rows) == len(want) == 55
    assert [r.to_dict() for r in rows] == want and rows == want
    row, line = rows[7], want[7]
    assert isinstance(row, flexfem.Row) and isinstance(row, Mapping)
    assert list(row) == list(row.keys()) == list(line) == ["index", "params", "design_hash", "result"]
    assert len(row) == 4 and "result" in row and "error" not in row and 3 not in row
    assert row.get("error") is None and row.get("error", 0) == 0
    with pytest.raises(KeyError):
        row["error"]
    result = row["result"]
    assert isinstance(result, flexfem.Row) and result == line["result"]
    assert result["k_bend"] == line["result"]["k_bend"] and type(result["k_bend"]) is float
    assert result["compliance"] == line["result"]["compliance"]  # a list of lists, as json gives
    assert dict(row.items())["params"] == line["params"] and row.values()[0] == line["index"]
    assert repr(row) == repr(line) and json.loads(json.dumps(row.to_dict())) == line
    assert pickle.loads(pickle.dumps(row)) == line and type(pickle.loads(pickle.dumps(row))) is dict


def test_sweep_columns_equal_the_cli_csv_cells(tmp_path):
    # Sweep.columns() and to_pandas() against `flexfem sweep --csv`: the same columns (names
    # with units for pandas) and every cell the same number (the CSV writes the shortest text
    # that round-trips, so equality is exact).
    case = CASES / "ruiz2019_hinge_sweep.json"
    path = tmp_path / "t.csv"
    code, _, err = cli("sweep", case, "--csv", path)
    assert code == 0, err
    header, *lines = [line.split(",") for line in path.read_text().splitlines()]
    s = flexfem.sweep(case)
    cols = s.columns()
    assert [name.split(" [")[0] for name in header] == list(cols)
    assert len(lines) == 55 and all(len(a) == 55 for a in cols.values())
    for k, (name, a) in enumerate(cols.items()):
        cells = [line[k] for line in lines]
        if name == "error":
            assert a.dtype == np.float64 and np.isnan(a).all()  # no error row: no cell, NaN
        elif a.dtype == object:  # text (the material's name)
            assert list(a) == cells, name
        else:
            assert a.dtype in (np.float64, np.int64, bool), name
            assert np.array_equal(a, np.array([json.loads(c) for c in cells])), name
    assert cols["index"].dtype == np.int64 and cols["hinge.t"].dtype == np.float64
    pd = pytest.importorskip("pandas")
    df = s.to_pandas()
    assert list(df.columns) == header
    pd.testing.assert_frame_equal(df, pd.read_csv(path), check_exact=True)


def test_sweep_with_vary_equals_the_sweep_case():
    base = json.loads(HINGE.read_text())
    vary = {"hinge.t": [1, 1.5, 2, 2.5, 3], "hinge.R": {"from": 2, "to": 12, "steps": 11}}
    a = flexfem.sweep(base, vary=vary).rows()
    b = flexfem.sweep(CASES / "ruiz2019_hinge_sweep.json").rows()
    assert len(a) == len(b) == 55 and a == b
    # A design's row holds the result of that hinge run on its own.
    one = flexfem.hinge("circular_notch", "Al7075", R=2, t=1, w=10, h=10, blank_length=20)
    assert a[0]["params"] == {"hinge.t": 1, "hinge.R": 2}
    assert a[0]["result"]["k_bend"] == one.k_bend


def test_sweep_fields_keeps_only_those():
    rows = flexfem.sweep(HINGE, vary={"hinge.t": [1, 2]}, fields=["k_bend"]).rows()
    assert [sorted(r["result"]) for r in rows] == [["k_bend"], ["k_bend"]]


def test_threads_option_gives_the_same_result():
    base = flexfem.run(MODAL)
    assert flexfem.run(MODAL, threads=1) == base
    assert flexfem.sweep(HINGE, vary={"hinge.t": [1, 2]}, threads=1).rows() == flexfem.sweep(
        HINGE, vary={"hinge.t": [1, 2]}, threads=2
    ).rows()


def test_solves_release_the_gil():
    # A Python thread counts while another runs a long solve: with the GIL held through the
    # solve it could not count at all inside the solve's window.
    # The stage FRF with its direct check (a complex sparse solve per frequency): about 1 s.
    case = FRF
    window = {}

    def solve():
        window["start"] = time.perf_counter()
        flexfem.run(case, threads=1)
        window["end"] = time.perf_counter()

    ticks = []
    t = threading.Thread(target=solve)
    t.start()
    while t.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.0005)
    t.join()
    inside = [x for x in ticks if window["start"] + 0.005 < x < window["end"] - 0.005]
    duration = window["end"] - window["start"]
    assert duration > 0.05, f"the solve took {duration:.3f} s: too short to tell"
    # A tick every 0.5 ms (plus scheduling): at least one per 5 ms of the solve.
    assert len(inside) >= duration / 0.005 - 2, (len(inside), duration)
