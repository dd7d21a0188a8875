"""The command line's way onto Dask (``penumbra ... --dask SCHEDULER``, docs/python.md): the
command writes a request (JSON), runs ``python3 -m penumbra._driver REQUEST RESULT``, and reads
the result back to write its usual outputs. Jobs:

- ``sun_hours``: {"scene", "study": {...}, "receivers": [owners] or null} -> JSON {"document":
  the merged exact document, "warnings": [...]};
- ``shadow_times``: {"scene", "light", "steps": [[time, azimuth, elevation, dx, dy, dz]], "exact",
  culling, "receivers"} -> JSON {"documents": [one shadow document a step], "warnings"};
- ``illuminance``: {"scene", "points": a file of N x 6 float64} -> the file of E (N float64),
  E per light (N x lights float64, row by row) and the holding object (N int64, -1 for none).

Exit status 2 with ``penumbra: error: ...`` on standard error for bad input, as the command."""

import json
import logging
import sys

import numpy as np

from . import InputError
from . import dask as pd


def run(request, result_path):
    job = request["job"]
    client = request["scheduler"]
    tasks = request.get("tasks")
    if job == "sun_hours":
        study = pd.sun_hours(request["scene"], client=client, tasks=tasks, exact=True,
                             receivers=request.get("receivers"), **request["study"])
        with open(result_path, "w", encoding="utf-8") as out:
            json.dump({"document": study.document, "warnings": study.warnings}, out)
    elif job == "illuminance":
        points = np.fromfile(request["points"], dtype=np.float64).reshape(-1, 6)
        total, lights, holder = pd._illuminance_arrays(request["scene"], points, client, tasks,
                                                       retries=2)
        with open(result_path, "wb") as out:
            for array, kind in ((total, np.float64), (lights, np.float64), (holder, np.int64)):
                np.ascontiguousarray(array, dtype=kind).tofile(out)
    elif job == "shadow_times":
        culling = {k: request[k] for k in ("range_fraction", "full_scale_lux", "range_lux")}
        documents, warnings = pd.shadow_times(request["scene"], request["steps"], request["light"],
                                              client=client, receivers=request.get("receivers"),
                                              exact=request["exact"], tasks=tasks, **culling)
        with open(result_path, "w", encoding="utf-8") as out:
            json.dump({"documents": documents, "warnings": warnings}, out)
    else:
        raise ValueError(f"unknown job {job!r}")


def main():
    logging.getLogger("distributed").setLevel(logging.ERROR)
    request_path, result_path = sys.argv[1:3]
    with open(request_path, encoding="utf-8") as request:
        try:
            run(json.load(request), result_path)
        except InputError as error:
            print(f"penumbra: error: {error}", file=sys.stderr)
            return 2
        except OSError as error:  # the scheduler cannot be reached, a file cannot be read
            print(f"penumbra: error: --dask: {error}", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
