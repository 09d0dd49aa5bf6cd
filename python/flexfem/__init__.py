"""flexfem from Python: the engine of the ``flexfem`` command line, in the same process.

A case is a ``dict`` (the JSON of a case file as Python values), the path of a case file
(``str`` or :class:`pathlib.Path`; files it names, such as a ``mesh``, are found beside it), or
the JSON text of a case. Units are flexfem's: mm, N, MPa, s, tonne; angles in degrees.

Functions:

- :func:`run` — the result ``flexfem run CASE`` prints, as a ``dict``;
- :func:`check` — validate without solving (``flexfem check``);
- :func:`schema` — the JSON Schema of case files (``flexfem schema``);
- :func:`hinge` — one flexure hinge, with its 6×6 compliance as a numpy array;
- :func:`sweep` — the designs of a sweep as an iterator of rows (``flexfem sweep``), with
  :meth:`Sweep.columns` (numpy) and :meth:`Sweep.to_pandas`;
- :func:`matrices` — the reduced K and M as ``scipy.sparse`` matrices;
- :func:`state_space` — A, B, C, D of an ``frf`` case as numpy arrays.

Errors: a bad case raises :class:`CaseError` with the JSON path ``flexfem`` names when it
exits with code 2; a failed analysis raises :class:`AnalysisError` (exit code 1). The solves
run without the GIL; ``threads`` (``--threads``) sets their worker threads, by default one per
core (or ``RAYON_NUM_THREADS``).
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any, Dict, Iterator, List, Optional, Union

import numpy as np

from . import _flexfem

__all__ = [
    "AnalysisError",
    "CaseError",
    "Hinge",
    "Row",
    "Sweep",
    "check",
    "hinge",
    "matrices",
    "run",
    "schema",
    "state_space",
    "sweep",
]

__version__ = _flexfem.__version__

Row = _flexfem.Row
# A read-only mapping over a sweep line (see its docstring): a Mapping for isinstance checks.
Mapping.register(Row)

Case = Union[Dict[str, Any], str, "os.PathLike[str]"]


class CaseError(ValueError):
    """A bad case: what ``flexfem run`` refuses with exit code 2.

    Attributes:
        path: JSON path of the offending field, e.g. ``hinge.t`` or ``fkp[2].s`` (``.`` for
            the case as a whole), as in the command line's message.
        message: what is wrong and what is allowed (includes the value).
    """

    def __init__(self, path: str, message: str):
        super().__init__(path, message)
        self.path = path
        self.message = message

    def __str__(self) -> str:
        return f"case file error at `{self.path}`: {self.message}"


class AnalysisError(RuntimeError):
    """A failed analysis (a numerical failure with its context): ``flexfem run``'s exit code 1.

    Attributes:
        context: which query or load case failed, e.g. ``fkp[2]``.
        message: what went wrong.
    """

    def __init__(self, context: str, message: str):
        super().__init__(context, message)
        self.context = context
        self.message = message

    def __str__(self) -> str:
        return f"analysis failed at `{self.context}`: {self.message}"


def run(case: Case, *, threads: Optional[int] = None) -> Dict[str, Any]:
    """Runs a case; returns the result ``flexfem run CASE`` prints, as a ``dict``.

    Args:
        case: a case ``dict``, a case file's path, or a case's JSON text.
        threads: worker threads of the solve (``--threads``); ``None``: one per core.

    Raises:
        CaseError: the case is bad (the JSON path and what is allowed).
        AnalysisError: the analysis failed.
    """
    return _flexfem.run(_case(case), threads)


def check(case: Case) -> str:
    """Validates a case without solving it (``flexfem check``); returns its analysis kind.

    A sweep case is checked as ``flexfem check`` checks it: its axes, and the first design and
    each varied path at its last value. What ``flexfem check`` prints as ``warning: …`` (the
    warnings of a run that depend on the case alone: hinges outside their calibrated ranges,
    implausible materials) is issued as one :class:`UserWarning` each.

    Raises:
        CaseError: what ``flexfem run`` would refuse, with the same JSON path.
    """
    return _flexfem.check(_case(case))


def schema() -> Dict[str, Any]:
    """The JSON Schema (draft 2020-12) of case files, as ``flexfem schema`` prints it."""
    return _flexfem.schema()


class Hinge:
    """A flexure hinge characterised in its blank (the result of :func:`hinge`).

    Attributes:
        compliance: 6×6 compliance at the free blank end face centre, numpy, rows/columns
            (ux, uy, uz, rx, ry, rz); mm/N, 1/N, rad/(N·mm).
        result: the whole result ``dict`` (as ``flexfem run`` of the hinge case).
        k_bend: compliant-axis rotational stiffness M_y/θ_y, N·mm/rad.
        k_bend_off: stiff-axis rotational stiffness M_z/θ_z, N·mm/rad.
        k_torsion: torsional stiffness, N·mm/rad.
        k_axial: axial stiffness, N/mm.
        max_rotation_deg: rotation at which the peak stress reaches the allowable, degrees
            (``None`` when the material has none).
    """

    def __init__(self, result: Dict[str, Any], compliance: np.ndarray):
        self.result = result
        self.compliance = compliance
        self.k_bend = result["k_bend"]
        self.k_bend_off = result["k_bend_off"]
        self.k_torsion = result["k_torsion"]
        self.k_axial = result["k_axial"]
        self.max_rotation_deg = result.get("max_rotation_deg")

    @property
    def stiffness(self) -> np.ndarray:
        """The 6×6 stiffness, the inverse of :attr:`compliance` (N/mm, N, N·mm/rad)."""
        return np.linalg.inv(self.compliance)

    def __repr__(self) -> str:
        return f"Hinge(k_bend={self.k_bend:.6g} N·mm/rad, k_axial={self.k_axial:.6g} N/mm)"


def hinge(type: str, material: Union[str, Dict[str, Any]] = "Al7075", **dims: Any) -> Hinge:
    """Characterises one flexure hinge in its blank (the ``hinge`` analysis).

    Args:
        type: the hinge family, e.g. ``"circular_notch"``, ``"corner_filleted"``,
            ``"elliptical"``, ``"leaf"`` (see the case-file reference).
        material: a built-in material name or ``{"E", "nu", "density", "yield", ...}``.
        **dims: the hinge's dimensions and options in mm (``R``, ``t``, ``w``, ``h``,
            ``blank_length``, ...), as the case's ``hinge`` object takes them.

    Returns:
        a :class:`Hinge`, whose ``compliance`` is a numpy array built from the solver's values.

    Raises:
        CaseError: a bad dimension, with its path (``hinge.t``, ...).
    """
    case = {"analysis": "hinge", "material": material, "hinge": {"type": type, **dims}}
    result, compliance = _flexfem.hinge(case)
    return Hinge(result, compliance)


class Sweep:
    """The designs of a sweep, run in parallel; iterate for their rows in index order.

    Each item is the design's line of ``flexfem sweep`` as a :class:`Row` (a read-only
    mapping): ``index``, ``params`` (varied path → value), ``design_hash`` and ``result`` — or
    ``error`` for a design that failed (the others go on; :attr:`failed` counts them). Designs
    run while you iterate. For the whole table, :meth:`columns` (numpy arrays) and
    :meth:`to_pandas` build it column by column from the lines, without a dict per row.
    """

    def __init__(self, native: Any):
        self._native = native
        self._rows: List[Row] = []
        self._columns: Optional[tuple] = None

    def __len__(self) -> int:
        """Number of designs."""
        return len(self._native)

    def __iter__(self) -> Iterator[Row]:
        yield from self._rows
        while True:
            batch = self._native.next_rows()
            if not batch:
                return
            self._rows.extend(batch)
            yield from batch

    @property
    def axes(self) -> List[str]:
        """The varied paths (the design index runs over them, the last fastest)."""
        return self._native.axes

    @property
    def failed(self) -> int:
        """Designs that failed so far (their rows hold ``error``)."""
        return self._native.failed

    def _finish(self) -> None:
        """Runs the designs still to run."""
        if len(self._rows) < len(self):
            self._rows.extend(self._native.rest_rows())

    def rows(self) -> List[Row]:
        """Every design's row, in index order (runs the designs still to run)."""
        self._finish()
        return list(self._rows)

    def _table(self) -> tuple:
        self._finish()
        if self._columns is None:
            names, headed, arrays = self._native.columns()
            self._columns = (_unique(names), _unique(headed), arrays)
        return self._columns

    def columns(self) -> Dict[str, np.ndarray]:
        """The table of :meth:`to_csv` as ``{column: numpy array}``, one entry per design.

        Columns: ``index``, each varied path, every scalar leaf of the result under its
        dotted name (``k_bend``, ``compliance.4.4``, ``load_cases.0.max_stress``; arrays of more
        than 16 numbers and lists of text are left out, as in the CSV), then ``error``; a name
        that comes twice (a result echoing a varied parameter) gets ``.1`` the second time, as
        ``pandas.read_csv`` names it. A column
        of integers is int64, of numbers float64 (NaN where a row has none, e.g. an error row),
        of booleans bool, of text or mixed values object (``None`` where a row has none).
        Built on the Rust side from the lines, in parallel (runs the designs still to run).
        """
        names, _, arrays = self._table()
        return dict(zip(names, arrays))  # zip-checked: both from one table, one per column

    def to_csv(self) -> str:
        """The table ``flexfem sweep --csv`` writes: one row per design, the varied parameters
        and the scalar results (with units in the column names)."""
        self._finish()
        return self._native.table_csv()

    def to_pandas(self):
        """The table of :meth:`to_csv` as a ``pandas.DataFrame``, with the same column names
        (units in brackets), built from :meth:`columns` (pandas is optional:
        ``pip install pandas``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("Sweep.to_pandas needs pandas: pip install pandas") from e

        _, headed, arrays = self._table()
        return pd.DataFrame(dict(zip(headed, arrays)), copy=False)  # zip-checked: as above


def _unique(names: List[str]) -> List[str]:
    """Column names made unique as ``pandas.read_csv`` makes them: a name seen before gets
    ``.1``, ``.2``, ... (a result that echoes a varied parameter, e.g. ``parameters.t``)."""
    seen: Dict[str, int] = {}
    out = []
    for name in names:
        unique = name
        while unique in seen:
            seen[name] += 1
            unique = f"{name}.{seen[name]}"
        seen.setdefault(name, 0)
        seen[unique] = 0
        out.append(unique)
    return out


def sweep(
    case: Case,
    vary: Optional[Dict[str, Any]] = None,
    *,
    fields: Optional[List[str]] = None,
    full: bool = False,
    threads: Optional[int] = None,
) -> Sweep:
    """Runs the full factorial of a sweep (``flexfem sweep``); returns an iterator of rows.

    Args:
        case: a sweep case (``"analysis": "sweep"``), or a base case when ``vary`` is given.
        vary: ``{path: values}``; values a list or ``{"from", "to", "steps"}``, e.g.
            ``{"hinge.t": [1, 1.5, 2], "hinge.R": {"from": 2, "to": 12, "steps": 11}}``.
        fields: keep only these result fields (dotted paths, ``--fields``).
        full: keep every result field (``--full``).
        threads: worker threads, one design each (``--threads``); ``None``: one per core.

    Raises:
        CaseError: a bad sweep or base case, with the path in the sweep case (``vary.…``,
            ``base.…``).
    """
    return Sweep(_flexfem.SweepRun(_case(case), vary, fields, full, threads))


def matrices(case: Case, *, threads: Optional[int] = None) -> Dict[str, Any]:
    """The reduced stiffness and mass of a static, modal, transient or frf case's model.

    The equations of ``flexfem run --export-matrices`` (supports removed, rigid links
    eliminated, DOFs of framed nodes in the node's frame).

    Returns:
        ``{"K": scipy.sparse.csr_matrix (N/mm, N/rad, N·mm/rad), "M": ... (tonne, tonne·mm²),
        "dofs": [(node, dof), ...] per equation, "node_frame": [bool, ...]}``; the values are
        the solver's own buffers (no copy, no JSON).
    """
    import scipy.sparse as sp

    raw = _flexfem.matrices(_case(case), threads)
    out: Dict[str, Any] = {"dofs": raw["dofs"], "node_frame": raw["node_frame"]}
    for name in ("K", "M"):
        data, indices, indptr, shape = raw[name]
        out[name] = sp.csr_matrix((data, indices, indptr), shape=shape, copy=False)
    return out


def state_space(case: Case, *, threads: Optional[int] = None) -> Dict[str, np.ndarray]:
    """The state-space model ẋ = A x + B u, y = C x + D u of an ``frf`` case (time in s).

    States are the retained modes' coordinates and rates; D is the static correction (see the
    README, "Frequency response, state-space models, matrix export").

    Returns:
        ``{"A", "B", "C", "D", "omega" (rad/s), "zeta"}`` as numpy arrays over the solver's
        buffers (column-major, Fortran order).
    """
    return _flexfem.state_space(_case(case), threads)


def _case(case: Case) -> Any:
    """A path-like case becomes its path string; dicts and text pass unchanged."""
    if isinstance(case, (dict, str)):
        return case
    if isinstance(case, os.PathLike):
        return os.fspath(case)
    return case
