#pragma once
// Errors that reach the user: each says where (file, line:column or JSON path) and what.

#include <stdexcept>
#include <string>

namespace hikari {

/// An input the user gave (scene, mesh, image, option) is wrong. The message is complete and
/// printed as `hikari: error: <message>`; the program exits with status 1.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The render was stopped by the user (SIGINT / SIGTERM); nothing is written.
class Interrupted : public std::runtime_error {
  public:
    Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace hikari
