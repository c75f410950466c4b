#include "json_out.hpp"

#include "dcel/io/json_reader.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::cli {

std::string json_point(Point p) {
    std::string out;
    io::JsonWriter w(out);
    w.raw('[');
    if (!w.number(p.x)) io::fail_not_finite("point", p.x);
    w.raw(", ");
    if (!w.number(p.y)) io::fail_not_finite("point", p.y);
    w.raw(']');
    w.flush();
    return out;
}

std::string json_name(const FaceNames* names, FaceId f) {
    if (names == nullptr || (*names)[f].empty()) return "null";
    return json_string((*names)[f]);
}

std::string json_location_members(const Dcel& d, const Location& l, const FaceNames* names) {
    switch (l.kind) {
        case Location::Kind::Vertex: return "\"vertex\": " + std::to_string(l.vertex.index());
        case Location::Kind::Face: {
            std::string s = "\"face\": " + std::to_string(l.face.index());
            if (names != nullptr) s += ", \"name\": " + json_name(names, l.face);
            return s;
        }
        case Location::Kind::Edge: {
            const FaceId left = d.face(half_edge_of(l.edge, 0));
            const FaceId right = d.face(half_edge_of(l.edge, 1));
            std::string s = "\"edge\": " + std::to_string(l.edge.index()) + ", \"faces\": [" + std::to_string(left.index()) +
                            ", " + std::to_string(right.index()) + "]";
            if (names != nullptr) s += ", \"names\": [" + json_name(names, left) + ", " + json_name(names, right) + "]";
            return s;
        }
    }
    return {};
}

std::string json_stab_members(const std::vector<StabPiece>& pieces, const FaceNames* names) {
    std::string faces;
    std::string face_names;
    std::string list;
    for (const StabPiece& p : pieces) {
        if (!list.empty()) list += ", ";
        switch (p.kind) {
            case StabPiece::Kind::Face:
                list += "{\"face\": " + std::to_string(p.face.index()) + "}";
                faces += (faces.empty() ? "" : ", ") + std::to_string(p.face.index());
                face_names += (face_names.empty() ? "" : ", ") + json_name(names, p.face);
                break;
            case StabPiece::Kind::Edge:
                list += "{\"edge\": " + std::to_string(p.edge.index()) + (p.along ? ", \"along\": true}" : "}");
                break;
            case StabPiece::Kind::Vertex: list += "{\"vertex\": " + std::to_string(p.vertex.index()) + "}"; break;
        }
    }
    std::string s = "\"faces\": [" + faces + "]";
    if (names != nullptr) s += ", \"names\": [" + face_names + "]";
    return s + ", \"pieces\": [" + list + "]";
}

}  // namespace dcel::cli
