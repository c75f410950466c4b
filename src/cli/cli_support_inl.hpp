#pragma once

#include "dcel/error.hpp"

namespace dcel::cli {

template <class F>
auto with_source(const std::string& path, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const InvalidInput& e) {
        throw InvalidInput(e.kind(), display_name(path) + ": " + e.what(), e.vertices(), e.edges());
    }
}

}  // namespace dcel::cli
