#pragma once
// The case a binding is given: a case file's TOML text, or the case as a tree of dicts, lists and numbers (what
// mdr.run(material=..., ...) builds in Python), read without text.

#include <pybind11/pybind11.h>

#include <string>

#include "mdr/io/case_template.hpp"

namespace mdr::python {

/// The case `case_` (a str: TOML text; a dict of str keys to dicts, lists, bool, int, float and str: the tree),
/// named `source` in messages. TypeError for any other value, naming its dotted key; mdr::InvalidInput for an
/// integer beyond 64 bits and for malformed TOML text.
io::CaseTemplate case_template(const pybind11::handle& case_, const std::string& source);

/// The tree `table` as Python values (dicts, lists, bool, int, float, str): the inverse of what case_template reads
/// from a dict.
pybind11::dict tree_object(const io::CaseTable& table);

}  // namespace mdr::python
