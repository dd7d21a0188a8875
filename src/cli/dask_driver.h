#pragma once
// `--dask SCHEDULER` (docs/python.md, "The command line on Dask"): a verb hands the heavy part
// of its work to a Dask cluster through the Python module's driver (python/penumbra/_driver.py)
// and writes its outputs itself, as it does without --dask, from the merged result.

#include <string>

#include <nlohmann/json.hpp>

namespace penumbra::cli {

// runs the driver on request (its "job" and arguments; "scheduler" is added) and returns the
// path of the result file it wrote, in a directory removed when the process ends. Throws
// InputError naming --dask when the driver refuses the input or cannot run (its message on
// standard error).
std::string run_on_dask(const std::string& scheduler, nlohmann::json request);

// returns a path for a file the request refers to, in the same directory.
std::string dask_scratch_file(const std::string& name);

}  // namespace penumbra::cli
