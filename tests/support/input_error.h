#pragma once
// Reading the error that bad input produces, in tests.

#include <string>

#include "hikari/core/error.h"

namespace hikari::testing {

/// The message of the InputError that `f()` throws, or "" when it throws none.
template <class F>
std::string input_error_of(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace hikari::testing
