#pragma once
/// \file
/// The declared fields of a control type and of the parts it holds (load_control.hpp, shore.hpp): what its Python
/// class shows (python/bindings/bind_controls.cpp) and the case file's keys of its numbers, which a sweep of a case
/// given as objects sets (io::CaseObjects).

namespace mdr::drivers {

/// One field of a control type (or of a part of one), as its Python class shows it: a keyword of the constructor and
/// a read-only property. The type of `member` says whether the keyword is required: a number is, an optional part
/// defaults to None and a list to empty.
template <class Control, class Value>
struct ControlField {
    using Type = Control;
    using ValueType = Value;
    const char* name;           ///< the keyword and property, e.g. "spring_constant"
    Value Control::*member;     ///< the field it sets and reads
    const char* unit;           ///< SI unit of its numbers, e.g. "N/m"; "" for none
    const char* documentation;  ///< one line
    /// The case file's dotted key of its number(s), e.g. "load.spring_constant" (a list of pairs: `KEY[i][j]`); "" for
    /// a part, whose own fields() name the keys of its numbers.
    const char* key;
};

/// A part of a control type that the case brings (a Shore test's, given as the control itself): a read-only
/// property of its Python class, no keyword.
template <class Control, class Value>
struct ControlPart : ControlField<Control, Value> {};

/// The ControlField of `member`, its numbers under the case file's `key`.
template <class Control, class Value>
constexpr ControlField<Control, Value> control_field(const char* name, Value Control::*member, const char* unit,
                                                     const char* documentation, const char* key) {
    return {name, member, unit, documentation, key};
}

/// The ControlPart of `member`.
template <class Control, class Value>
constexpr ControlPart<Control, Value> control_part(const char* name, Value Control::*member, const char* unit,
                                                   const char* documentation) {
    return {{name, member, unit, documentation, ""}};
}

}  // namespace mdr::drivers
