// Reading the sites of a diagram from any input of docs/contract.md: balls text, vdrc, PDB or mmCIF.
// Every failure is an Input_error naming the file, the 1-based line (0 for the whole file) and the reason.
#pragma once

#include <string>
#include <vector>

#include "io/atom_label.h"
#include "predicates/site.h"

namespace apollonius {

// Which atoms of a structure file become sites; balls and vdrc inputs ignore these.
struct Read_options {
  bool keep_hydrogens = false;
  bool keep_waters = false;
  bool atom_labels = false;  // fill Site_input::labels for structure files
};

enum class Input_format { balls, vdrc, structure };

// Invariant: sites is not empty, and sites[i] is the i-th ball or atom of the input, in input order;
// labels[i] is the atom of sites[i] for a structure read with Read_options::atom_labels, else labels is
// empty; lines is empty or has one entry per site.
struct Site_input {
  std::vector<Site> sites;
  Input_format format;
  std::vector<Atom_label> labels;
  std::vector<std::size_t> lines;  // the 1-based line of each site in balls and vdrc text; empty for structures
};

// Structure files are recognised by extension (.pdb .ent .cif .mmcif, each optionally .gz); anything else
// by content, whatever its name. path "-" reads standard input, named "<stdin>" in messages.
Site_input read_sites(const std::string& path, const Read_options& options);

// The same for content already in memory (detected by content only); name is used in messages.
Site_input read_sites_from_text(const std::string& content, const std::string& name, const Read_options& options);

// Sites from arrays in memory (the Python module's numpy arrays): centres holds x y z of each site, one
// site after the other, and weights one w per site. Checked as files are: no site at all, or a value that
// is NaN or infinite, is an Input_error naming the array ("centres" or "weights"), the 0-based site and
// the reason, e.g. "centres: site 3, z: not a finite number: nan". So is a count beyond Site_index.
std::vector<Site> sites_from_arrays(const double* centres, const double* weights, std::size_t count);

}  // namespace apollonius
