"""Errors as Python exceptions: a bad case raises `flexfem.CaseError` with the JSON path the
command line names when it exits with code 2; a failed analysis raises `AnalysisError` (exit 1)."""

import json

import numpy as np
import pytest

import flexfem
from conftest import CASES, cli, cli_error_path

HINGE = json.loads((CASES / "ruiz2019_hinge_revolute.json").read_text())

BAD = {
    # A hinge thicker than its blank height; an unknown field; a wrong type; an unknown kind.
    "thick_notch": {**HINGE, "hinge": {**HINGE["hinge"], "t": 20}},
    "unknown_field": {**HINGE, "hinge": {**HINGE["hinge"], "thickness": 2}},
    "wrong_type": {**HINGE, "material": 7075},
    "unknown_analysis": {"analysis": "hinges"},
    "negative_radius": {**HINGE, "hinge": {**HINGE["hinge"], "R": -1}},
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_case_error_path_equals_cli(name, tmp_path):
    case = tmp_path / f"{name}.json"
    case.write_text(json.dumps(BAD[name]))
    code, _, err = cli("run", case)
    assert code == 2, err
    want = cli_error_path(err)
    for given in (BAD[name], case, str(case), json.dumps(BAD[name])):
        with pytest.raises(flexfem.CaseError) as e:
            flexfem.run(given)
        assert e.value.path == want
        assert str(e.value) in err
        with pytest.raises(flexfem.CaseError) as c:
            flexfem.check(given)
        assert c.value.path == want


def test_bad_sweep_names_the_varied_path(tmp_path):
    # A thickness no hinge can have: `flexfem check` refuses it (exit 2) at the varied path,
    # `flexfem sweep` writes an error row for that design (exit 1) and runs the other.
    case = {"analysis": "sweep", "base": HINGE, "vary": {"hinge.t": [-1, 2]}}
    path = tmp_path / "bad_sweep.json"
    path.write_text(json.dumps(case))
    code, _, err = cli("check", path)
    assert code == 2, err
    with pytest.raises(flexfem.CaseError) as e:
        flexfem.check(case)
    assert e.value.path == cli_error_path(err)
    code, out, err = cli("sweep", path)
    assert code == 1, err
    want = sorted((json.loads(line) for line in out.splitlines()), key=lambda r: r["index"])
    s = flexfem.sweep(HINGE, vary={"hinge.t": [-1, 2]})
    assert s.rows() == want and s.failed == 1 and "error" in want[0]
    # In the columns the error row has its text under `error` and NaN for the results.
    cols = s.columns()
    assert list(cols["error"]) == [want[0]["error"], None]
    assert np.isnan(cols["k_bend"][0]) and cols["k_bend"][1] == want[1]["result"]["k_bend"]


def test_bad_vary_raises_before_running(tmp_path):
    # An axis that is neither a list nor a range: the sweep case itself is bad (exit 2).
    case = {"analysis": "sweep", "base": HINGE, "vary": {"hinge.t": "thin"}}
    path = tmp_path / "bad_axis.json"
    path.write_text(json.dumps(case))
    code, _, err = cli("sweep", path)
    assert code == 2, err
    with pytest.raises(flexfem.CaseError) as e:
        flexfem.sweep(HINGE, vary={"hinge.t": "thin"})
    assert e.value.path == cli_error_path(err)


def test_failed_analysis_raises_analysis_error(tmp_path):
    # A valid kinematics case whose FKP has no solution: exit 1 with the context `fkp[1]`.
    case = {
        "analysis": "kinematics",
        "mechanism": {"L": 109.215, "b": 47.91, "alpha0_deg": 45},
        "fkp": [{"s": [0, 0, 0]}, {"s": [100, -100, 0]}],
    }
    path = tmp_path / "unreachable.json"
    path.write_text(json.dumps(case))
    code, _, err = cli("run", path)
    assert code == 1, err
    with pytest.raises(flexfem.AnalysisError) as e:
        flexfem.run(case)
    assert e.value.context == "fkp[1]"
    assert str(e.value) in err


def test_missing_file_and_bad_json_are_case_errors():
    with pytest.raises(flexfem.CaseError) as e:
        flexfem.run("no/such/case.json")
    assert e.value.path == "." and "cannot read case file" in e.value.message
    with pytest.raises(flexfem.CaseError) as j:
        flexfem.run('{"analysis": ')
    assert j.value.path == "." and "not valid JSON" in j.value.message


def test_wrong_argument_types():
    with pytest.raises(TypeError):
        flexfem.run(42)
    with pytest.raises(ValueError):
        flexfem.run(HINGE, threads=0)
