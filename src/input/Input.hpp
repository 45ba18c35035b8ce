#pragma once
// Reads an input deck into a Teuchos::ParameterList: Peridigm XML by default, YAML for .yaml/.yml.
// Only parsing happens here; validateInput() (InputSchema.hpp) decides whether the content is usable.
// Any unreadable or unparsable file is an InputError naming the file.
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace pf {

Teuchos::RCP<Teuchos::ParameterList> readInput(const std::string& path);

// Directory holding the deck ("." if none): relative file names in the deck resolve against it.
std::string inputDirectory(const std::string& path);

// A deck-relative file name (mesh, node-set ids) made usable from the working directory.
std::string resolvePath(const std::string& name, const std::string& inputDir);

}  // namespace pf
