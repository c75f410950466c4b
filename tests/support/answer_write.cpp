// Step 4 of the answer trials: the text, in the setup's conventions and in
// one of the forms docs/checking.md allows (answer_spellings.hpp).
#include <array>
#include <numeric>
#include <string>
#include <vector>

#include "support/answer_steps.hpp"
#include "support/answer_text.hpp"

namespace dcel::test_support::spell {
namespace {

// Step 4 for a dump: half-edges and faces renumbered, then turned around
// for faces on the right, then counted from 1. Ids out of range stay out of
// range. Each is undone by the checker's reading of the conventions, so
// the dump read is the one the oracle judged: exactly where twin is an
// involution, and where it is not, both are broken.
DcelDump dump_as_written(DcelDump d, const check::Conventions& conventions, Choices& c, std::string& story,
                         std::vector<bool>& nulls_as_zero) {
    const auto halves = static_cast<Index>(d.half_edges.size());
    const auto faces = static_cast<Index>(d.faces.size());
    if (c.one_in(2)) {
        std::vector<Index> ph(halves), pf(faces);
        std::iota(ph.begin(), ph.end(), Index{0});
        std::iota(pf.begin(), pf.end(), Index{0});
        shuffle(ph, c);
        shuffle(pf, c);
        auto h_of = [&](HalfEdgeId h) { return h.index() < halves ? HalfEdgeId(ph[h.index()]) : h; };
        auto f_of = [&](FaceId f) { return f.index() < faces ? FaceId(pf[f.index()]) : f; };
        DcelDump out;
        out.vertices = d.vertices;
        for (const HalfEdgeId h : d.vertex_out) out.vertex_out.push_back(h_of(h));
        out.half_edges.resize(halves);
        for (Index h = 0; h < halves; ++h) {
            const HalfEdgeRecord& r = d.half_edges[h];
            out.half_edges[ph[h]] = {r.origin, h_of(r.twin), h_of(r.next), h_of(r.prev), f_of(r.face)};
        }
        out.faces.resize(faces);
        for (Index f = 0; f < faces; ++f) {
            FaceDump& n = out.faces[pf[f]];
            n.outer = h_of(d.faces[f].outer);
            for (const HalfEdgeId h : d.faces[f].inner) n.inner.push_back(h_of(h));
            n.isolated = d.faces[f].isolated;
        }
        d = std::move(out);
        story += "renumbered half-edges and faces\n";
    }
    if (conventions.face_on_right) {
        // Each half-edge turned around: it starts where its twin does, and
        // next and prev swap; vertex_out names the twin of what it named.
        std::vector<HalfEdgeRecord> turned = d.half_edges;
        for (Index h = 0; h < halves; ++h) {
            const Index t = d.half_edges[h].twin.index();
            if (t < halves) turned[h].origin = d.half_edges[t].origin;
            std::swap(turned[h].next, turned[h].prev);
        }
        for (HalfEdgeId& h : d.vertex_out) {
            if (h.index() < halves) h = d.half_edges[h.index()].twin;
        }
        d.half_edges = std::move(turned);
    }
    if (conventions.one_based) {
        auto up = [](auto& id) {
            using Id = std::decay_t<decltype(id)>;
            if (!id.is_null()) id = Id(id.index() + 1);
        };
        for (HalfEdgeId& h : d.vertex_out) up(h);
        for (HalfEdgeRecord& r : d.half_edges) {
            up(r.origin);
            up(r.twin);
            up(r.next);
            up(r.prev);
            up(r.face);
        }
        for (FaceDump& f : d.faces) {
            up(f.outer);
            for (HalfEdgeId& h : f.inner) up(h);
            for (VertexId& v : f.isolated) up(v);
        }
        // In a 1-based dump 0 is the null id too (where a null may stand).
        nulls_as_zero.assign(2, false);
        nulls_as_zero[0] = c.one_in(2);  // vertex_out
        nulls_as_zero[1] = c.one_in(2);  // outer
    }
    return d;
}

void write_null_or_zero(AnswerText& w, bool zero) {
    if (zero) {
        w.id(0);
    } else {
        w.literal("null");
    }
}

std::string dump_json(const DcelDump& d, const std::vector<bool>& nulls_as_zero, Choices& c) {
    AnswerText w(c);
    const bool out_zero = !nulls_as_zero.empty() && nulls_as_zero[0];
    const bool outer_zero = !nulls_as_zero.empty() && nulls_as_zero[1];
    w.begin_object();
    std::vector<std::size_t> order{0, 1, 2, 3};
    if (c.one_in(2)) shuffle(order, c);
    for (const std::size_t part : order) {
        switch (part) {
            case 0:
                w.key("vertices");
                w.begin_array();
                for (const Point& p : d.vertices) {
                    w.begin_array();
                    w.number(p.x);
                    w.number(p.y);
                    w.end_array();
                }
                w.end_array();
                break;
            case 1:
                if (d.vertex_out.empty()) break;
                w.key("vertex_out");
                w.begin_array();
                for (const HalfEdgeId h : d.vertex_out) {
                    if (h.is_null()) {
                        write_null_or_zero(w, out_zero);
                    } else {
                        w.id(h.index());
                    }
                }
                w.end_array();
                break;
            case 2: {
                w.key("half_edges");
                w.begin_array();
                const bool shuffled_keys = c.one_in(2);
                for (const HalfEdgeRecord& r : d.half_edges) {
                    w.begin_object();
                    std::vector<std::size_t> keys{0, 1, 2, 3, 4};
                    if (shuffled_keys) shuffle(keys, c);
                    for (const std::size_t k : keys) {
                        static constexpr std::array<std::string_view, 5> kNames{"origin", "twin", "next", "prev", "face"};
                        w.key(kNames[k]);
                        const Index values[] = {r.origin.index(), r.twin.index(), r.next.index(), r.prev.index(),
                                                r.face.index()};
                        w.id(values[k]);
                    }
                    w.maybe_ignored_member({"origin", "twin", "next", "prev", "face"});
                    w.end_object();
                }
                w.end_array();
                break;
            }
            default:
                w.key("faces");
                w.begin_array();
                for (const FaceDump& f : d.faces) {
                    w.begin_object();
                    w.key("outer");
                    if (f.outer.is_null()) {
                        write_null_or_zero(w, outer_zero);
                    } else {
                        w.id(f.outer.index());
                    }
                    // inner and isolated default to [].
                    if (!f.inner.empty() || c.one_in(2)) {
                        w.key("inner");
                        w.begin_array();
                        for (const HalfEdgeId h : f.inner) w.id(h.index());
                        w.end_array();
                    }
                    if (!f.isolated.empty() || c.one_in(2)) {
                        w.key("isolated");
                        w.begin_array();
                        for (const VertexId v : f.isolated) w.id(v.index());
                        w.end_array();
                    }
                    w.end_object();
                }
                w.end_array();
                break;
        }
    }
    w.maybe_ignored_member({"vertices", "vertex_out", "half_edges", "faces"});
    w.end_object();
    return w.take();
}

// ---- Step 4 for cycles and rings

// A cycle or ring as written: reversed when asked (faces on the right: the
// first vertex stays first, which is how the checker turns it back), then
// maybe closed by repeating its first vertex. Closed always when its first
// and last vertices are equal: the checker drops a last vertex equal to the
// first, exactly once, so only then does it read the walk written.
IdRing as_written(IdRing ring, bool reverse, bool close) {
    if (reverse) std::reverse(ring.begin(), ring.end());
    if (!ring.empty() && (close || (ring.size() >= 2 && ring.front() == ring.back()))) ring.push_back(ring.front());
    return ring;
}

}  // namespace

std::string faces_text(const std::vector<IdRing>& cycles, const TrialSetup& s, Choices& c, std::string& story) {
    const bool closed = c.one_in(3);
    std::vector<IdRing> written;
    for (const IdRing& cycle : cycles) {
        written.push_back(as_written(cycle, s.conventions.face_on_right, closed && c.one_in(2)));
    }
    AnswerText w(c);
    // Bare [[v, ...], ...] reads as faces when the first cycle has a vertex
    // (or there is none).
    const bool bare = c.one_in(2) && (s.give_kind || written.empty() || !written.front().empty());
    if (!bare) {
        w.begin_object();
        w.maybe_ignored_member({"faces"});
        w.key("faces");
    }
    w.begin_array();
    for (const IdRing& cycle : written) {
        w.begin_array();
        for (const Index v : cycle) w.id(s.conventions.one_based ? v + 1 : v);
        w.end_array();
    }
    w.end_array();
    if (!bare) {
        w.maybe_ignored_member({"faces"});
        w.end_object();
    }
    story += bare ? "written as a bare list\n" : "written as an object\n";
    return w.take();
}

namespace {

// A point for an id that names no vertex (a corruption's): one no vertex has.
Point point_of(const PlanarGraph& g, Index v) {
    if (v < g.vertices.size()) return g.vertices[v];
    for (double x = 0.5;; x += 1.0) {
        const Point p{x, -x / 3};
        if (std::none_of(g.vertices.begin(), g.vertices.end(), [&](const Point& q) { return q.x == p.x && q.y == p.y; })) {
            return p;
        }
    }
}

class RegionsWriter {
public:
    RegionsWriter(const PlanarGraph& g, const TrialSetup& s, Choices& c, bool by_points, bool altitude)
        : g_(g), s_(s), c_(c), by_points_(by_points), altitude_(altitude), w_(c) {}

    AnswerText& w() { return w_; }

    void ring(const IdRing& r) {
        w_.begin_array();
        for (const Index v : r) {
            if (by_points_) {
                const Point p = point_of(g_, v);
                w_.begin_array();
                w_.number(p.x);
                w_.number(p.y);
                if (altitude_) w_.number(static_cast<double>(v) * 0.5);
                w_.end_array();
            } else {
                w_.id(s_.conventions.one_based ? v + 1 : v);
            }
        }
        w_.end_array();
    }

    void ring_list(const IdPolygon& p) {
        w_.begin_array();
        for (const IdRing& r : p) ring(r);
        w_.end_array();
    }

    // {"shell": ring, "holes": [ring, ...]}, in either order; "holes" may be
    // left out when there are none.
    void shell_and_holes(const IdPolygon& p) {
        w_.begin_object();
        const bool holes_first = c_.one_in(2);
        const bool holes = p.size() > 1 || c_.one_in(2);
        auto write_holes = [&] {
            if (!holes) return;
            w_.key("holes");
            w_.begin_array();
            for (std::size_t r = 1; r < p.size(); ++r) ring(p[r]);
            w_.end_array();
        };
        if (holes_first) write_holes();
        w_.key("shell");
        if (p.empty()) {
            w_.begin_array();
            w_.end_array();
        } else {
            ring(p[0]);
        }
        if (!holes_first) write_holes();
        w_.maybe_ignored_member({"shell", "holes"});
        w_.end_object();
    }

    void geometry(const std::vector<IdPolygon>& ps, bool allow_polygon) {
        w_.begin_object();
        const bool type_last = c_.one_in(3);
        const char* type = allow_polygon && ps.size() == 1 && c_.one_in(2) ? "\"Polygon\"" : "\"MultiPolygon\"";
        if (!type_last) {
            w_.key("type");
            w_.literal(type);
        }
        w_.key("coordinates");
        if (type[1] == 'P') {
            ring_list(ps.front());
        } else {
            w_.begin_array();
            for (const IdPolygon& p : ps) ring_list(p);
            w_.end_array();
        }
        if (type_last) {
            w_.key("type");
            w_.literal(type);
        }
        w_.maybe_ignored_member({"type", "coordinates"});
        w_.end_object();
    }

private:
    const PlanarGraph& g_;
    const TrialSetup& s_;
    Choices& c_;
    bool by_points_, altitude_;
    AnswerText w_;
};

// The polygons in consecutive groups of 0 to 3: the Features or geometries
// of a GeoJSON collection.
std::vector<std::vector<IdPolygon>> groups(const std::vector<IdPolygon>& ps, Choices& c) {
    std::vector<std::vector<IdPolygon>> out;
    for (std::size_t i = 0; i < ps.size();) {
        const std::size_t n = std::min(ps.size() - i, c.below(4));
        out.emplace_back(ps.begin() + static_cast<std::ptrdiff_t>(i), ps.begin() + static_cast<std::ptrdiff_t>(i + n));
        i += n;
        if (n == 0 && out.size() > ps.size() + 3) break;  // bytes of zeros: no endless empty groups
    }
    if (out.empty() || c.one_in(3)) out.emplace_back();
    // Zero bytes give groups of none: put what is left in one.
    std::size_t placed = 0;
    for (const auto& g : out) placed += g.size();
    if (placed < ps.size()) out.back().insert(out.back().end(), ps.begin() + static_cast<std::ptrdiff_t>(placed), ps.end());
    return out;
}

}  // namespace

std::string regions_text(const PlanarGraph& g, const std::vector<IdPolygon>& polygons, const TrialSetup& s, Choices& c,
                         std::string& story) {
    const bool rings_kind = s.kind == check::AnswerKind::Rings;
    // GeoJSON (polygons only) is coordinates; otherwise either.
    const std::size_t form = c.below(rings_kind ? 2 : 4);  // object / bare / shell-and-holes objects / GeoJSON
    const bool geojson = !rings_kind && form == 3;
    const bool by_points = geojson || c.one_in(2);
    bool altitude = by_points && c.one_in(4);
    const bool closed = geojson ? !c.one_in(4) : c.one_in(3);
    // Polygon rings are written the other way for faces on the right; ring
    // answers have no direction to turn.
    const bool reverse = s.conventions.face_on_right && !rings_kind;
    std::vector<IdPolygon> written;
    for (const IdPolygon& p : polygons) {
        IdPolygon& out = written.emplace_back();
        for (const IdRing& r : p) out.push_back(as_written(r, reverse, closed && !c.one_in(4)));
    }
    // Detection reads a bare list by the depth of its first number and, for
    // rings of coordinates, by the length of the first position: a bare form
    // only where that says the kind written.
    bool bare = form == 1;
    if (bare && !s.give_kind) {
        const bool first = !written.empty() && !written.front().empty() && !written.front().front().empty();
        if (rings_kind) {
            bare = first && by_points;
            altitude = altitude && !bare;
        } else {
            bare = first && (by_points || written.front().front().size() != 2);
        }
    }
    RegionsWriter rw(g, s, c, by_points, altitude);
    AnswerText& w = rw.w();
    const char* key = rings_kind ? "rings" : "polygons";
    if (geojson) {
        const std::size_t shape = c.below(
            5);  // MultiPolygon or Polygon / FeatureCollection / GeometryCollection / Feature / nested
        story += std::string("written as GeoJSON (") +
                 (shape == 0   ? "a geometry"
                  : shape == 1 ? "a FeatureCollection"
                  : shape == 2 ? "a GeometryCollection"
                  : shape == 3 ? "a Feature"
                               : "nested collections") +
                 ")\n";
        if (shape == 0) {
            rw.geometry(written, true);
        } else if (shape == 3) {
            w.begin_object();
            w.key("type");
            w.literal("\"Feature\"");
            w.key("geometry");
            if (written.empty() && c.one_in(2)) {
                w.literal("null");
            } else {
                rw.geometry(written, true);
            }
            w.maybe_ignored_member({"type", "geometry"});
            w.end_object();
        } else {
            const bool features = shape == 1 || (shape == 4 && c.one_in(2));
            w.begin_object();
            w.key("type");
            w.literal(features ? "\"FeatureCollection\"" : "\"GeometryCollection\"");
            w.key(features ? "features" : "geometries");
            w.begin_array();
            for (const std::vector<IdPolygon>& group : groups(written, c)) {
                if (features) {
                    w.begin_object();
                    w.key("type");
                    w.literal("\"Feature\"");
                    if (c.one_in(3)) {
                        w.key("properties");
                        w.literal(R"({"name": "f"})");
                    }
                    w.key("geometry");
                    if (group.empty() && c.one_in(2)) {
                        w.literal("null");  // a Feature without geometry adds nothing
                    } else if (shape == 4 && c.one_in(2)) {
                        w.begin_object();
                        w.key("type");
                        w.literal("\"GeometryCollection\"");
                        w.key("geometries");
                        w.begin_array();
                        rw.geometry(group, true);
                        w.end_array();
                        w.end_object();
                    } else {
                        rw.geometry(group, true);
                    }
                    w.end_object();
                } else if (shape == 4 && c.one_in(2)) {
                    w.begin_object();
                    w.key("geometries");
                    w.begin_array();
                    rw.geometry(group, true);
                    w.end_array();
                    w.key("type");
                    w.literal("\"GeometryCollection\"");
                    w.end_object();
                } else {
                    rw.geometry(group, true);
                }
            }
            w.end_array();
            w.maybe_ignored_member({"type", "features", "geometries"});
            w.end_object();
        }
        return w.take();
    }
    story += std::string(bare ? "written as a bare list" : "written as an object") +
             (by_points ? " of coordinate rings" : " of id rings") + (altitude ? " with altitudes" : "") + "\n";
    if (!bare) {
        w.begin_object();
        w.maybe_ignored_member({key});
        w.key(key);
    }
    w.begin_array();
    for (const IdPolygon& p : written) {
        if (rings_kind) {
            for (const IdRing& r : p) rw.ring(r);
        } else if (form == 2 && c.below(4) != 0) {
            rw.shell_and_holes(p);
        } else {
            rw.ring_list(p);
        }
    }
    w.end_array();
    if (!bare) w.end_object();
    return w.take();
}

std::string dump_text(const DcelDump& d, const check::Conventions& conventions, Choices& c, std::string& story) {
    std::vector<bool> nulls_as_zero;
    const DcelDump written = dump_as_written(d, conventions, c, story, nulls_as_zero);
    return dump_json(written, nulls_as_zero, c);
}

}  // namespace dcel::test_support::spell
