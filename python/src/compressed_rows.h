// Lists of lists of integers as numpy arrays in compressed rows: row i is values[offsets[i]:offsets[i + 1]].
#pragma once

#include <pybind11/numpy.h>

#include <cstdint>

namespace apollonius::python {

// Invariant: offsets has one entry per row and one more, from 0 to len(values), ascending.
struct Compressed_rows {
  pybind11::array_t<std::int64_t> offsets, values;
};

// The rows row_of(item) of every item of `items`, copied once into arrays that numpy owns.
template <class Items, class Row_of>
Compressed_rows compressed_rows(const Items& items, Row_of row_of) {
  std::size_t total = 0;
  for (const auto& item : items) total += row_of(item).size();
  Compressed_rows rows{pybind11::array_t<std::int64_t>(static_cast<pybind11::ssize_t>(items.size() + 1)),
                       pybind11::array_t<std::int64_t>(static_cast<pybind11::ssize_t>(total))};
  std::int64_t* offset = rows.offsets.mutable_data();
  std::int64_t* value = rows.values.mutable_data();
  offset[0] = 0;
  for (const auto& item : items) {
    for (const auto v : row_of(item)) *value++ = static_cast<std::int64_t>(v);
    offset[1] = offset[0] + static_cast<std::int64_t>(row_of(item).size());
    ++offset;
  }
  return rows;
}

// Row i (negative counts from the end, as Python's) as a view into the values; IndexError out of range.
inline pybind11::object row_view(const pybind11::array_t<std::int64_t>& offsets,
                                 const pybind11::array_t<std::int64_t>& values, pybind11::ssize_t i) {
  const pybind11::ssize_t n = offsets.size() - 1;
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw pybind11::index_error("index out of range");
  return values[pybind11::slice(offsets.at(i), offsets.at(i + 1), 1)];
}

}  // namespace apollonius::python
