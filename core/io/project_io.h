#pragma once
// The .gridifs project file: validated loading with JSON-path errors and
// atomic saving with a `~` backup.
#include <filesystem>
#include <string>

#include "base/errors.h"
#include "model/project.h"
#include "schema/validation.h"

namespace gridifs {

/// Parses and validates project JSON text. Throws ModelError whose path is a JSON path
/// (`functions[2].ops[0].k`) and whose message says what was expected.
Project parseProject(const std::string& text);

/// Reads and parses a project file, with the leaves of its construction tree
/// (readConstructionLeaves). Throws ModelError (bad content; the message names no file) or
/// IoError (unreadable). Never modifies the file.
Project loadProject(const std::filesystem::path& file);

/// Reads the files named by the leaves of `project`'s construction tree (paths relative to
/// `projectFile`'s folder, or to the working folder when it is empty) and makes the project's
/// functions the tree's value again (model/construction_tree.h). Throws ModelError at the JSON path
/// of a leaf that is missing, unreadable, invalid or part of a cycle, or of an operation that
/// fails. loadProject does this for every file it reads.
void readConstructionLeaves(Project& project, const std::filesystem::path& projectFile);

/// Serialises to pretty JSON; parseProject(serializeProject(p)) == p.
std::string serializeProject(const Project& project);

/// Writes atomically: a temporary file in the same folder, flushed and renamed over
/// `file`; an existing `file` is first copied to `file~`. On any failure the old file
/// is intact and IoError is thrown.
void saveProject(const Project& project, const std::filesystem::path& file);

}  // namespace gridifs
