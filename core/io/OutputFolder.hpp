#pragma once
// The output folder of a run, checked before anything is solved: a run must not spend an hour
// on step 1 and then find that it cannot write. prepareOutputFolder creates the folder if
// needed, proves it writable with a probe file, and removes what an earlier run left there
// that this run would rewrite (result.pvd, result_*.vtu/.pvtu and their pieces, steps.csv,
// contact.csv, summary.json, hidden temporaries), so that no stale step outlives a new run.
// Files it does not know are left alone. Throws InputError with one sentence.
#include <string>
#include <vector>

namespace contactlab {

// Returns the names of the stale files removed (for the log).
std::vector<std::string> prepareOutputFolder(const std::string& path);

// A run continued in its own folder (--restart) keeps its outputs but not the temporaries a
// killed writer left (".<name>.tmp.<pid>"); returns their names. Throws InputError when one
// cannot be removed.
std::vector<std::string> removeTemporaries(const std::string& path);

}  // namespace contactlab
