// Reading the sites of a diagram from any input of docs/contract.md: balls text, vdrc, PDB or mmCIF.
// Every failure is an Input_error naming the file, the 1-based line (0 for the whole file) and the reason.
#pragma once

#include <string>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

// Which atoms of a structure file become sites; balls and vdrc inputs ignore these.
struct Read_options {
  bool keep_hydrogens = false;
  bool keep_waters = false;
};

enum class Input_format { balls, vdrc, structure };

// Invariant: sites is not empty, and sites[i] is the i-th ball or atom of the input, in input order;
// lines is empty or has one entry per site.
struct Site_input {
  std::vector<Site> sites;
  Input_format format;
  std::vector<std::size_t> lines;  // the 1-based line of each site in balls and vdrc text; empty for structures
};

// Structure files are recognised by extension (.pdb .ent .cif .mmcif, each optionally .gz); anything else
// by content, whatever its name. path "-" reads standard input, named "<stdin>" in messages.
Site_input read_sites(const std::string& path, const Read_options& options);

// The same for content already in memory (detected by content only); name is used in messages.
Site_input read_sites_from_text(const std::string& content, const std::string& name, const Read_options& options);

}  // namespace apollonius
