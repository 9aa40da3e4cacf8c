#pragma once
// A .msh file's declared counts against its size, before libgmsh reads it (private to io/).
//
// libgmsh 4.8 trusts the counts of a .msh file: a node block that declares 2,000,000,000 nodes in a
// 150-byte file makes it allocate tens of gigabytes before it notices the data is missing (found by
// fuzz/fuzz_gmsh.cpp). check_msh_counts reads the counts that size gmsh's allocations - the entities and
// their tag lists of $Entities (format 4), the node blocks of $Nodes, the counts of $Elements and the
// entity count of $NodeData, $ElementData and $ElementNodeData - in ASCII and binary files of formats
// 2 and 4, and refuses a count the rest of its section cannot hold (each item takes at least a few
// tokens or bytes).
// First of all the file must start with the line $MeshFormat: gmsh reads any other file, whatever
// its name, as a .geo script, which can run commands.
// It checks nothing else: everything else is gmsh's to read and report.
#include <filesystem>
#include <string>

namespace seflex::io::gmsh {

/// Throws InputError "FILE:LINE: $Nodes: a block of N nodes, but the section holds at most M; expected
/// a count that matches the data (a truncated or corrupted .msh file?)" for a count too large for the
/// file, and "FILE:1: the file starts with '...'; expected a gmsh mesh (MSH format 2 or 4), whose first
/// line is $MeshFormat ..." for a file gmsh would not read as a mesh. `file` names the file in messages.
void check_msh_counts(const std::filesystem::path& path, const std::string& file);

}  // namespace seflex::io::gmsh
