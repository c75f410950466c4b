// The error model: InvalidInput for input that is not a planar straight-line
// graph (or not a document of the expected form), TopologyError when a
// requested edit would break the structure. Messages are one line, name the
// offending ids, and say how to fix the input where there is a fix.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel {

enum class InputErrorKind {
    Syntax,         // not JSON, or not a document of the expected shape
    Shape,          // JSON, but a value of the wrong type or arity, or a missing key
    BadIndex,       // an index out of range, negative or not an integer
    BadCoordinate,  // NaN, infinite, or beyond the double range
    TooLarge,       // more elements than 32-bit ids can name
    DuplicatePoint,
    SelfLoop,
    DuplicateEdge,
    Crossing,      // two edges cross at a point inside both
    VertexOnEdge,  // a vertex lies inside an edge (a T-junction or a touch)
    Overlap,       // two collinear edges share more than a point
};

[[nodiscard]] const char* to_string(InputErrorKind kind);

class InvalidInput : public std::invalid_argument {
public:
    InvalidInput(InputErrorKind kind, const std::string& message, std::vector<VertexId> vertices = {},
                 std::vector<EdgeId> edges = {})
        : std::invalid_argument(message), kind_(kind), vertices_(std::move(vertices)), edges_(std::move(edges)) {}

    [[nodiscard]] InputErrorKind kind() const { return kind_; }
    [[nodiscard]] const std::vector<VertexId>& vertices() const { return vertices_; }  // offending vertices
    [[nodiscard]] const std::vector<EdgeId>& edges() const { return edges_; }          // offending input edges

private:
    InputErrorKind kind_;
    std::vector<VertexId> vertices_;
    std::vector<EdgeId> edges_;
};

class TopologyError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

}  // namespace dcel
