#pragma once
// YAML text to a Teuchos::ParameterList, read by yaml-cpp (a complete YAML 1.2 parser: UTF-8
// and its byte-order mark, indentless block sequences, escapes in double quotes, block
// scalars, anchors), typed as Teuchos' own YAML reader types it:
//   - a mapping is a sublist named by its key; an empty value is an empty sublist;
//   - a plain scalar is a bool (true/false/yes/no, any case), else an int (in int's range),
//     else a double, else a string; a quoted or block scalar is always a string;
//   - a sequence of scalars is a Teuchos::Array of the least specific of its items' types
//     (int with double gives double; anything with a string gives strings; bools are strings);
//     a sequence of such sequences is a Teuchos::TwoDArray (the rows of equal length).
// Refused with an InputError naming the label, the line and column and the key path: text
// that is not YAML, a key given twice in one mapping, a mapping inside a sequence, a document
// that is not one mapping with a single top-level key.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

namespace contactlab {

// The list is named by the document's one top-level key and holds what is under it.
Teuchos::RCP<Teuchos::ParameterList> parseYamlParameterList(const std::string& text,
                                                            const std::string& label);

}  // namespace contactlab
