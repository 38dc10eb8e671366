#pragma once
// Validation of user parameter lists against lists of valid parameters (each entry with a
// default and a doc string), with messages that name the file, the key path and the valid
// choices. Teuchos' own validateParameters gives correct but long messages and rejects
// `E: 200000` (read by YAML as an int) where a double is expected, so values are first coerced
// to the valid entry's type.
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace contactlab {

// Checks every key of `user` against `valid` (recursively), coerces numbers and strings to the
// valid entry's type, runs the entry's validator, and fills in defaults (marked
// ParameterEntry::isDefault, unlike the values given). Sublists of `valid`
// are required to be sublists in `user` too. Throws InputError naming `where` (a file name) and
// the key path, e.g. "scene.yaml: unknown key 'Youngs' in Materials/body/linear-elastic; valid
// keys: E, nu, density".
void validateAndSetDefaults(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                            const std::string& where, const std::string& path = "");

// Marks a sublist of a valid list as passed through (e.g. to NOX, which checks it itself): its
// user contents are kept as given, only strings that read as a bool, an int or a double (from
// --set) are converted to that type.
Teuchos::ParameterList& markPassThrough(Teuchos::ParameterList& valid);
bool isPassThrough(const Teuchos::ParameterList& valid);

// Sets `path=value` in `list`, with path components separated by '/', e.g.
// "Mesh/rectangle/nx=20". The value is stored as a string unless the entry exists already, in
// which case it is parsed as that entry's type; validateAndSetDefaults converts strings later.
void applyOverride(Teuchos::ParameterList& list, const std::string& assignment);

// Comma-separated keys of a list, for messages.
std::string keysOf(const Teuchos::ParameterList& list);

}  // namespace contactlab
