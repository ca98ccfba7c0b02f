// Which atom of a structure file a site is: its identifiers in gemmi's hierarchy (model, chain, residue,
// atom), for callers that map diagram results back to atoms (the Python module's read_sites).
#pragma once

#include <string>

namespace apollonius {

struct Atom_label {
  std::string chain;          // author chain name
  std::string residue_name;   // e.g. "GLY"
  int residue_number = 0;     // author sequence number (gemmi's -999 when the file gives none)
  char insertion_code = ' ';  // ' ' when none
  std::string atom_name;      // e.g. "CA"
  std::string element;        // e.g. "C", "Se", as gemmi names it
  char alternate_location = ' ';  // ' ' when none
  int serial = 0;             // atom serial number (mmCIF: _atom_site.id)
};

}  // namespace apollonius
