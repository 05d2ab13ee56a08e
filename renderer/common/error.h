#pragma once
// Error types shared by every layer. They are caught once, at the top of main, and turned into
// one line `depthscope: error: ...` with an exit code (DESIGN decision 8).
#include <stdexcept>
#include <string>

namespace ds {

// Runtime or input failure (bad file, Vulkan error, unwritable folder): exit code 1.
class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Bad input data (a broken glTF, a missing file). Message form: "FILE: WHAT". Exit code 1.
class InputError : public Error {
  public:
    using Error::Error;
};

// Bad command line or unknown setting / bad setting value: exit code 2.
class UsageError : public Error {
  public:
    using Error::Error;
};

}  // namespace ds
