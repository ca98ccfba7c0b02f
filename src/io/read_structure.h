// Atoms of a PDB or mmCIF structure as sites: centre = atom position, weight = van der Waals radius.
#pragma once

#include <string>
#include <vector>

#include "io/atom_label.h"
#include "io/read_sites.h"
#include "predicates/site.h"

namespace apollonius {

// The first model of a structure, read through gemmi.
// - content == nullptr: reads the file path_or_name, optionally gzipped (.gz); mmCIF if the name ends in
//   .cif or .mmcif (before any .gz), PDB otherwise.
// - content != nullptr: parses content, mmCIF if its first line that is neither blank nor a '#' comment
//   starts with "data_", PDB otherwise; path_or_name only names it in messages.
// Atoms are kept in file order, less hydrogens and waters (unless options keep them) and all alternate
// locations of an atom but the first seen. Throws Input_error, also when no atom is left. When labels is
// not null, it receives the label of each site.
std::vector<Site> read_structure(const std::string& path_or_name, const std::string* content,
                                 const Read_options& options, std::vector<Atom_label>* labels = nullptr);

}  // namespace apollonius
