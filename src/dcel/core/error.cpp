#include "dcel/error.hpp"

namespace dcel {

const char* to_string(InputErrorKind kind) {
    switch (kind) {
        case InputErrorKind::Syntax: return "syntax";
        case InputErrorKind::Shape: return "shape";
        case InputErrorKind::BadIndex: return "bad-index";
        case InputErrorKind::BadCoordinate: return "bad-coordinate";
        case InputErrorKind::TooLarge: return "too-large";
        case InputErrorKind::DuplicatePoint: return "duplicate-point";
        case InputErrorKind::SelfLoop: return "self-loop";
        case InputErrorKind::DuplicateEdge: return "duplicate-edge";
        case InputErrorKind::Crossing: return "crossing";
        case InputErrorKind::VertexOnEdge: return "vertex-on-edge";
        case InputErrorKind::Overlap: return "overlap";
    }
    return "unknown";
}

}  // namespace dcel
