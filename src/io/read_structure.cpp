#include "io/read_structure.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>
#include <stdexcept>
#include <string_view>

#include <gemmi/fileutil.hpp>
#include <gemmi/gz.hpp>
#include <gemmi/mmread.hpp>

#include "io/input_error.h"
#include "io/text_input.h"

namespace apollonius {

namespace {

// Van der Waals radii in Angstrom, from A. Bondi (1964), "van der Waals Volumes and Radii",
// J. Phys. Chem. 68:441. C, N, O and S agree with the defaults of `voronota get-balls-from-atoms-file`.
//
//   element   radius
//   H, D      1.20
//   C         1.70
//   N         1.55
//   O         1.52
//   F         1.47
//   P         1.80
//   S         1.80
//   Cl        1.75
//   Br        1.85
//   I         1.98
//   Se        1.90
//   other     1.80   (default for every element not listed, and for an unknown element)
double van_der_waals_radius(gemmi::El element) {
  switch (element) {
    case gemmi::El::H:
    case gemmi::El::D: return 1.20;
    case gemmi::El::C: return 1.70;
    case gemmi::El::N: return 1.55;
    case gemmi::El::O: return 1.52;
    case gemmi::El::F: return 1.47;
    case gemmi::El::P: return 1.80;
    case gemmi::El::S: return 1.80;
    case gemmi::El::Cl: return 1.75;
    case gemmi::El::Br: return 1.85;
    case gemmi::El::I: return 1.98;
    case gemmi::El::Se: return 1.90;
    default: return 1.80;
  }
}

bool is_water(const std::string& residue_name) {
  return residue_name == "HOH" || residue_name == "WAT" || residue_name == "DOD" || residue_name == "H2O";
}

// gemmi reads "nan", "inf" and numbers beyond the double range as coordinates. They are bad input, as in
// balls text: no algorithm may see them (GMP even raises SIGFPE on converting one). gemmi keeps no line
// numbers, so the atom is named instead.
void check_finite_position(const gemmi::Atom& atom, const gemmi::Residue& residue, const gemmi::Chain& chain,
                           const std::string& name) {
  if (std::isfinite(atom.pos.x) && std::isfinite(atom.pos.y) && std::isfinite(atom.pos.z)) return;
  throw Input_error(name, 0, "not a finite coordinate: atom " + std::to_string(atom.serial) + " (" + atom.name +
                                 " of " + residue.name + " " + residue.seqid.str() + ", chain " + chain.name + ")");
}

// The sites of one model, in file order. Of the alternate locations of an atom only the first one seen
// is kept, so that each atom is one ball (one conformer); atoms without an altloc are always kept.
std::vector<Site> sites_of_model(const gemmi::Model& model, const Read_options& options, const std::string& name,
                                 std::vector<Atom_label>* labels) {
  std::vector<Site> sites;
  std::map<std::string, char> first_altloc;  // keyed by chain, residue number and atom name
  for (const gemmi::Chain& chain : model.chains) {
    for (const gemmi::Residue& residue : chain.residues) {
      if (!options.keep_waters && is_water(residue.name)) continue;
      for (const gemmi::Atom& atom : residue.atoms) {
        if (!options.keep_hydrogens && atom.is_hydrogen()) continue;
        if (atom.has_altloc()) {
          const std::string key = chain.name + ' ' + residue.seqid.str() + ' ' + atom.name;
          if (first_altloc.emplace(key, atom.altloc).first->second != atom.altloc) continue;
        }
        check_finite_position(atom, residue, chain, name);
        sites.push_back({atom.pos.x, atom.pos.y, atom.pos.z, van_der_waals_radius(atom.element.elem)});
        if (labels)
          labels->push_back(Atom_label{chain.name, residue.name, *residue.seqid.num, residue.seqid.icode, atom.name,
                                       atom.element.name(), atom.has_altloc() ? atom.altloc : ' ', atom.serial});
      }
    }
  }
  return sites;
}

// gemmi reports errors as std::runtime_error, with the line either as "Problem in line N: REASON" (PDB)
// or as "NAME:LINE:COLUMN: REASON" (CIF). This recovers the line and the reason, on one line.
Input_error input_error_from_gemmi(const std::string& name, const std::string& message) {
  static const std::regex pdb_location(R"(Problem in line (\d+): *([\s\S]*))");
  static const std::regex cif_location(R"((\d+):\d+: *([\s\S]*))");
  const std::string name_prefix = name + ":";
  const std::string after_name =
      message.compare(0, name_prefix.size(), name_prefix) == 0 ? message.substr(name_prefix.size()) : "";
  std::size_t line = 0;
  std::string reason = message;
  std::smatch match;
  if (std::regex_match(message, match, pdb_location) || std::regex_match(after_name, match, cif_location)) {
    line = std::stoul(match[1]);
    reason = match[2];
  }
  for (char& c : reason) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  reason.erase(reason.find_last_not_of(' ') + 1);
  return Input_error(name, line, reason);
}

// Columns 79-80 of PDB atom records hold the formal charge, which no radius needs; old files such as
// 1hpv.pdb have sequence numbers there, on which gemmi fails ("Wrong format for charge").
gemmi::PdbReadOptions pdb_read_options() {
  gemmi::PdbReadOptions options;
  options.max_line_length = 78;
  return options;
}

// Whether a line starts with the record name, in any case: gemmi's test (is_record_type), which compares
// the first four characters only.
bool starts_with_record(std::string_view line, std::string_view record) {
  if (line.size() < 4) return false;
  for (std::size_t i = 0; i < 4; ++i)
    if (std::toupper(static_cast<unsigned char>(line[i])) != record[i]) return false;
  return true;
}

// gemmi reads an atom coordinate (columns 31-38, 39-46, 47-54) as the longest number the field starts
// with, and a blank one as 0: "2,4 0.00" would be 2. Bad input, reported at its line.
void check_atom_coordinates(std::string_view line, const std::string& name, std::size_t number) {
  if (!starts_with_record(line, "ATOM") && !starts_with_record(line, "HETA")) return;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
  if (line.size() < 54) return;  // gemmi's "too short" error
  for (const std::size_t column : {30, 38, 46}) {
    std::string_view field = line.substr(column, 8);
    field.remove_prefix(std::min(field.find_first_not_of(' '), field.size()));
    field.remove_suffix(field.size() - (field.find_last_not_of(' ') + 1));
    const std::string columns = "columns " + std::to_string(column + 1) + "-" + std::to_string(column + 8);
    if (field.empty()) throw Input_error(name, number, "blank atom coordinate in " + columns);
    try {
      parse_number(field, name, number);
    } catch (const Input_error& e) {
      throw Input_error(name, number, "atom coordinate in " + columns + ": " + e.reason());
    }
  }
}

// gemmi 0.5.7 reads the distance of an SSBOND or LINK record (columns 74-78) from any such line longer
// than 73 bytes, and so reads past the end of a line of 74 to 77 (regression/gemmi_ssbond_overread.pdb).
// gemmi collects these records and CISPEP only for bonds, which no radius needs: they are blanked here,
// their line breaks kept so that gemmi's line numbers stay right. So are DBREF records (sequence database
// references): gemmi reads DBREF2's 10-column numbers into an int, which overflows
// (regression/gemmi_dbref2_integer_overflow.pdb).
// gemmi skips the rest of a line longer than it reads only up to a byte above 0x7f (its getc returns a
// signed char), and starts its next line there: such a "line" may be a short SSBOND record
// (regression/gemmi_line_split_at_high_byte.pdb). PDB is ASCII; such bytes can only stand in names or
// remarks, and become '?', so that gemmi splits lines where this function does. (NUL, which stops
// gemmi's skip too, is refused before: no text holds it.)
std::string gemmi_safe_pdb_text(std::string_view pdb, const std::string& name) {
  std::string kept;
  kept.reserve(pdb.size());
  std::size_t number = 1;
  for (std::size_t start = 0; start < pdb.size(); ++number) {
    const std::size_t end = std::min(pdb.find('\n', start), pdb.size() - 1) + 1;  // past the line break
    const std::string_view line = pdb.substr(start, end - start);
    check_atom_coordinates(line, name, number);
    if (starts_with_record(line, "SSBO") || starts_with_record(line, "LINK") || starts_with_record(line, "CISP") ||
        starts_with_record(line, "DBRE")) {
      kept += line.back() == '\n' ? "\n" : "";
    } else {
      for (const char c : line) kept += static_cast<unsigned char>(c) > 0x7f ? '?' : c;
    }
    start = end;
  }
  return kept;
}

// gemmi 0.5.7 reads mmCIF integers (sequence numbers, atom ids, charges, counts) with no overflow check:
// ten or more digits overflow an int (regression/gemmi_cif_integer_overflow.cif). A value whose leading
// digits are that long is refused, except in the decimal columns that gemmi reads as doubles.
bool is_decimal_column(std::string tag) {
  for (char& c : tag) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));  // tags ignore case
  for (const char* decimal : {"_atom_site.cartn_x", "_atom_site.cartn_y", "_atom_site.cartn_z", "_atom_site.occupancy",
                              "_atom_site.b_iso_or_equiv"})
    if (tag == decimal) return true;
  return false;
}

bool has_ten_leading_digits(const std::string& value) {
  std::size_t i = !value.empty() && (value[0] == '-' || value[0] == '+') ? 1 : 0;
  const std::size_t first = i;
  while (i < value.size() && std::isdigit(static_cast<unsigned char>(value[i]))) ++i;
  return i - first >= 10;
}

void check_cif_integer_lengths(const gemmi::cif::Block& block, const std::string& name) {
  const auto check = [&](const std::string& tag, const std::string& value) {
    if (has_ten_leading_digits(value))
      throw Input_error(name, 0, "number too long for gemmi's integers in " + tag + ": '" + value + "'");
  };
  for (const gemmi::cif::Item& item : block.items) {
    if (item.type == gemmi::cif::ItemType::Pair && !is_decimal_column(item.pair[0])) check(item.pair[0], item.pair[1]);
    if (item.type == gemmi::cif::ItemType::Loop && !item.loop.tags.empty()) {
      const std::vector<std::string>& tags = item.loop.tags;
      std::vector<bool> checked(tags.size());
      for (std::size_t t = 0; t < tags.size(); ++t) checked[t] = !is_decimal_column(tags[t]);
      for (std::size_t k = 0; k < item.loop.values.size(); ++k)
        if (checked[k % tags.size()]) check(tags[k % tags.size()], item.loop.values[k]);
    }
    if (item.type == gemmi::cif::ItemType::Frame) check_cif_integer_lengths(item.frame, name);
  }
}

gemmi::Structure parse_cif(const gemmi::cif::Document& document, const std::string& name) {
  for (const gemmi::cif::Block& block : document.blocks) check_cif_integer_lengths(block, name);
  return gemmi::make_structure(document);
}

gemmi::Structure parse_pdb(std::string_view pdb, const std::string& name) {
  reject_binary_data(pdb, name);
  const std::string text = gemmi_safe_pdb_text(pdb, name);
  return gemmi::read_pdb_from_memory(text.data(), text.size(), name, pdb_read_options());
}

gemmi::Structure parse_structure(const std::string& path_or_name, const std::string* content) {
  if (content == nullptr) {
    gemmi::MaybeGzipped input(path_or_name);
    if (gemmi::coor_format_from_ext(input.basepath()) == gemmi::CoorFormat::Mmcif) {
      return parse_cif(gemmi::cif::read(input), path_or_name);
    }
    const gemmi::CharArray text = gemmi::read_into_buffer(input);
    return parse_pdb(std::string_view(text.data(), text.size()), path_or_name);
  }
  // gemmi's own test: mmCIF if the first line that is not blank nor a '#' comment starts with "data_".
  const char* const begin = content->data();
  if (gemmi::coor_format_from_content(begin, begin + content->size()) == gemmi::CoorFormat::Mmcif) {
    return parse_cif(gemmi::cif::read_memory(content->data(), content->size(), path_or_name.c_str()), path_or_name);
  }
  return parse_pdb(*content, path_or_name);
}

}  // namespace

std::vector<Site> read_structure(const std::string& path_or_name, const std::string* content,
                                 const Read_options& options, std::vector<Atom_label>* labels) {
  gemmi::Structure structure;
  try {
    structure = parse_structure(path_or_name, content);
  } catch (const Input_error&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw input_error_from_gemmi(path_or_name, e.what());
  } catch (const std::logic_error& e) {
    // gemmi lets std::stoi and friends fail on malformed numbers: bad input too, not a bug here.
    throw input_error_from_gemmi(path_or_name, e.what());
  }
  std::vector<Site> sites;
  if (labels) labels->clear();
  if (!structure.models.empty()) sites = sites_of_model(structure.models.front(), options, path_or_name, labels);
  if (sites.empty()) throw Input_error(path_or_name, 0, "no atoms");
  return sites;
}

}  // namespace apollonius
