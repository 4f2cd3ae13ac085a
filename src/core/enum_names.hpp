#pragma once
// One table per enum of the names users write and read: the name of a
// value and the value of a name both come from it, so the two cannot drift.
//   constexpr EnumName<GroundKind> kGroundKinds[] = {{GroundKind::shadow, "shadow"}, ...};
//   name_of(kGroundKinds, kind);  value_of(kGroundKinds, "floor");  names_of(kGroundKinds)
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace facet {

template <typename E>
struct EnumName {
    E value;
    std::string_view name;
};

// "?" for a value the table lacks (a table is written with every value).
template <typename E, size_t N>
constexpr std::string_view name_of(const EnumName<E> (&table)[N], E value) {
    for (const EnumName<E>& entry : table)
        if (entry.value == value) return entry.name;
    return "?";
}

// The same name as a C string, for messages built with `+` and for lists
// of keys: a table's names are string literals, which end in '\0'.
template <typename E, size_t N>
constexpr const char* c_name_of(const EnumName<E> (&table)[N], E value) {
    return name_of(table, value).data();
}

template <typename E, size_t N>
constexpr std::optional<E> value_of(const EnumName<E> (&table)[N], std::string_view name) {
    for (const EnumName<E>& entry : table)
        if (entry.name == name) return entry.value;
    return std::nullopt;
}

// The names in the table's order: the choices an error lists.
template <typename E, size_t N>
std::vector<std::string_view> names_of(const EnumName<E> (&table)[N]) {
    std::vector<std::string_view> names;
    for (const EnumName<E>& entry : table) names.push_back(entry.name);
    return names;
}

}  // namespace facet
