"""feticon from Python: contact of elastic bodies by FETI, one run per call.

    import feticon
    result = feticon.run()                                # the Hertz benchmark
    result = feticon.run("model.inp", settings={"load_steps": 4})
    result = feticon.run({"problem": "hertz", "load": 1e6})  # problem-file keys as a dict
    result.summary["contact"]["total_normal_force"]       # summary.json as a dict
    result.displacements                                  # NumPy (nodes, 3)

A run writes no files unless `output` names a results folder (then the same files as
`feticon run --output`). Errors raise feticon.Error with feticon's one-line message. The
module runs on one rank; distributed runs stay on the command line (mpirun feticon run).
"""

import json
import os

from ._feticon import Error
from ._feticon import run as _run

__all__ = ["Error", "Result", "run"]


class Result:
    """A completed run.

    summary        summary.json's content (dict)
    coordinates    reference node coordinates, (nodes, 3), m
    displacements  node displacements, (nodes, 3), m
    cell_stress    volume-averaged Cauchy stress per cell, (cells, 6), Pa,
                   Voigt order [11, 22, 33, 12, 23, 31]
    von_mises      von Mises stress per cell, (cells,), Pa
    contact        contact_pressure.csv's columns (dict of arrays): pair, x, y, z,
                   normal_force (N), area (m^2), pressure and pressure_from_stress (Pa)
    """

    def __init__(self, raw):
        self.summary = json.loads(raw["summary"])
        self.coordinates = raw["coordinates"]
        self.displacements = raw["displacements"]
        self.cell_stress = raw["cell_stress"]
        self.contact = raw["contact"]
        self.von_mises = raw["von_mises"][:, 0]

    def pair_pressure(self, pair=0):
        """The contact columns of one contact pair (index into summary['contact']['pairs'])."""
        mine = self.contact["pair"] == pair
        return {key: column[mine] for key, column in self.contact.items()}


def _setting_text(value):
    """A setting's value as --set takes it: YAML scalars, lists in flow style."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple, dict)):
        return json.dumps(value)
    return str(value)


def run(problem=None, settings=None, output=None, quiet=True, verbose=False, overwrite=False):
    """Runs one problem and returns its Result.

    problem    None (the built-in Hertz benchmark), a path to a problem file (.yaml) or an
               input deck (.inp), or a dict of problem-file keys (docs/usage.md)
    settings   dict KEY: VALUE, as `feticon run --set KEY=VALUE` (dotted keys: "qp.rtol")
    output     results folder to write (None: no files)
    quiet      only warnings and errors on the terminal; verbose: also each QP iteration
    overwrite  replace an earlier run's results in `output`
    """
    problem_file, problem_text = "", None
    if isinstance(problem, dict):
        problem_text = json.dumps(problem)
    elif problem is not None:
        problem_file = os.fspath(problem)
    overrides = [f"{key}={_setting_text(value)}" for key, value in (settings or {}).items()]
    raw = _run(problem_file, problem_text, overrides, "" if output is None else os.fspath(output),
               quiet and not verbose, verbose, overwrite)
    return Result(raw)
