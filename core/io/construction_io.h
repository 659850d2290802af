#pragma once
// Reading and writing a project's construction tree (internal to io/; model/construction_tree.h
// says what it means), and reading the projects its file leaves name. Throws ModelError with a
// JSON path ("construction.root.children[1].file: ...").
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/project.h"

namespace gridifs::construction_io {

/// Reads a part's function set from its JSON object (the project reader, given by project_io).
using ReadPart = std::function<Project(const nlohmann::json& part, const std::string& path)>;
/// Writes a part's functions, transitions and space into `out`.
using WritePart = std::function<void(const Project& part, nlohmann::ordered_json& out)>;

/// "construction" of the root object, if present; file leaves are not read here.
std::optional<ConstructionTree> readConstruction(const nlohmann::json& root, const ReadPart& readPart);

/// Adds "construction" to the root object when the project has a tree.
void writeConstruction(const Project& project, nlohmann::ordered_json& root, const WritePart& writePart);

/// Reads one project file; `chain` holds the files being read around it (for cycles).
using LoadFile = std::function<Project(const std::filesystem::path& file, std::vector<std::filesystem::path>& chain)>;

/// Reads every file leaf of `tree` (paths relative to `folder`) with `load`. A file that is
/// missing, unreadable, invalid or already in `chain` (a cycle) throws ModelError at the leaf's
/// JSON path.
void readLeafFiles(ConstructionTree& tree, const std::filesystem::path& folder,
                   std::vector<std::filesystem::path>& chain, const LoadFile& load);

/// The canonical form of `file` used to find cycles (weakly canonical, absolute).
std::filesystem::path chainKey(const std::filesystem::path& file);

}  // namespace gridifs::construction_io
