// For a plugin whose effects are found at run time (one per file it reads): pfx_effect_desc.create
// says nothing of which effect it makes, so each effect needs a create function of its own. This
// makes a table of them at compile time, the I-th calling the plugin's create(I, host, out).
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include <pfx/pfx.h>

namespace pfx::plugin {

using CreateFunction = pfx_status (*)(const pfx_host* host, void** out_instance);
using IndexedCreate = pfx_status (*)(std::size_t index, const pfx_host* host, void** out_instance);

template <IndexedCreate Create, std::size_t I>
pfx_status create_effect_number(const pfx_host* host, void** out_instance) {
  return Create(I, host, out_instance);
}

template <IndexedCreate Create, std::size_t... I>
constexpr std::array<CreateFunction, sizeof...(I)> create_functions(std::index_sequence<I...>) {
  return {&create_effect_number<Create, I>...};
}

// create_functions<N, create>()[i] creates effect number i, for i < N.
template <std::size_t N, IndexedCreate Create>
constexpr std::array<CreateFunction, N> create_functions() {
  return create_functions<Create>(std::make_index_sequence<N>{});
}

}  // namespace pfx::plugin
