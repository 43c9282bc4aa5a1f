#pragma once
//! \file errors.hpp
//! The typed exceptions of geolab. Library code never prints; it throws one of these and the program prints.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace geolab {

//! Thrown by every unimplemented student stub. The grader reports a test that hits it as "not implemented".
//! \param function the name of the function the student has to write (the stubs pass `__func__`).
class NotImplemented : public std::logic_error {
public:
    explicit NotImplemented(const std::string& function);
    //! How many NotImplemented were constructed in this process (the grader's test runner reads it).
    static std::uint64_t count();
};

//! A file could not be read or written. what() is "FILE:LINE: reason" (line 0 when no line applies,
//! "element N" for binary formats).
class IoError : public std::runtime_error {
public:
    IoError(std::string file, std::size_t line, const std::string& reason);
    const std::string& file() const { return file_; }
    std::size_t line() const { return line_; }

private:
    std::string file_;
    std::size_t line_;
};

//! Input that is not a valid (manifold, consistently oriented) mesh. what() names the function, the reason
//! and the offending face / vertex indices, e.g. "build_mesh: complex edge (3 faces) at vertices 4-7, face 12".
class TopologyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace geolab
