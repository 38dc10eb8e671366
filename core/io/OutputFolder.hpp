#pragma once
// The output folder of a run, checked before anything is solved: a run must not spend an hour
// on step 1 and then find that it cannot write. prepareOutputFolder creates the folder if
// needed, proves it writable with a probe file, and removes what an earlier run wrote there,
// so that no stale step outlives a new run: the files the earlier run's manifest lists
// (OutputManifest.hpp) and their temporaries, nothing else; in a folder without a manifest
// (an older run's), the files named as a run's outputs (result.pvd, result_*.vtu/.pvtu and
// their pieces, steps.csv, contact*.csv, profile_*.csv, summary.json, checkpoint.h5,
// progress.log) and their temporaries. It then starts this run's manifest, empty. Throws
// InputError with one sentence.
#include <string>
#include <vector>

namespace contactlab {

// Refuses (InputError) a value of the input that becomes one file or folder name inside a
// folder: empty or blank, or with '/', '..' or a control character, it would name the folder
// itself or another one (results/../../x). `key` names it in the sentence ("scene.yaml: Name"),
// `use` says what it names ("the results folder results/<Name>").
void requirePlainName(const std::string& value, const std::string& key, const std::string& use);

// Returns the names of the stale files removed (for the log).
std::vector<std::string> prepareOutputFolder(const std::string& path);

// A run continued in its own folder (--restart) keeps its outputs but not the temporaries a
// killed writer left (".<name>.tmp.<pid>", of a name its manifest lists); returns their
// names. A folder without a manifest gets one listing its run's outputs. Throws InputError
// when a file cannot be removed or the manifest written.
std::vector<std::string> prepareContinuedFolder(const std::string& path);

}  // namespace contactlab
