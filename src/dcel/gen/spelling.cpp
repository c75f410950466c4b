#include "dcel/gen/spelling.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

#include "dcel/gen/rng.hpp"

namespace dcel::gen {

namespace {

enum class Form : std::uint8_t { Shortest, Scientific, ScientificPlus, Decimal, IntegralSignificand };

std::string chars(double v, std::chars_format f) {
    char buf[400];  // fixed notation of a double needs at most 1 + 309 + 1 + 767 digits only for values we never
                    // write that way: fixed is used for integral values below 2^1024, at most 310 characters
    const auto r = std::to_chars(buf, buf + sizeof buf, v, f);
    return std::string(buf, r.ptr);
}

// "1.2345e+16" -> digits "12345", point after 1 digit, exponent 16.
struct Scientific {
    std::string sign, digits;
    int exponent = 0;  // of the first digit
};

Scientific scientific(double v) {
    const std::string s = chars(v, std::chars_format::scientific);
    Scientific out;
    std::size_t i = 0;
    if (s[0] == '-') {
        out.sign = "-";
        i = 1;
    }
    const std::size_t e = s.find('e');
    for (std::size_t k = i; k < e; ++k) {
        if (s[k] != '.') out.digits += s[k];
    }
    out.exponent = std::stoi(s.substr(e + 1));
    return out;
}

std::string spelled(double v, Form f) {
    switch (f) {
        case Form::Shortest: return chars(v, std::chars_format::general);
        case Form::Scientific: {
            const Scientific s = scientific(v);
            std::string m = s.digits.substr(0, 1);
            if (s.digits.size() > 1) m += "." + s.digits.substr(1);
            return s.sign + m + "e" + std::to_string(s.exponent);
        }
        case Form::ScientificPlus: {
            std::string s = chars(v, std::chars_format::scientific);
            s[s.find('e')] = 'E';
            return s;
        }
        case Form::Decimal:
            if (std::trunc(v) == v) return chars(v, std::chars_format::fixed) + ".0";
            return chars(v, std::chars_format::general);
        case Form::IntegralSignificand: {
            const Scientific s = scientific(v);
            return s.sign + s.digits + "e" + std::to_string(s.exponent - static_cast<int>(s.digits.size()) + 1);
        }
    }
    return chars(v, std::chars_format::general);
}

class Writer {
public:
    explicit Writer(const Spelling& s) : s_(s) {}

    std::string write(const PlanarGraph& g) {
        if (s_.positional) {
            out_ += "[";
            vertices(g);
            out_ += comma();
            edges(g);
            out_ += "]";
        } else {
            out_ += "{";
            if (s_.newlines) out_ += "\n  ";
            for (int part = 0; part < 2; ++part) {
                if (part == 1) out_ += comma();
                const bool vertices_now = (part == 0) != s_.edges_first;
                out_ += vertices_now ? "\"vertices\":" : "\"edges\":";
                if (!s_.compact) out_ += " ";
                if (vertices_now) {
                    vertices(g);
                } else {
                    edges(g);
                }
            }
            if (s_.newlines) out_ += "\n";
            out_ += "}";
        }
        out_ += "\n";
        return std::move(out_);
    }

private:
    [[nodiscard]] std::string comma() const {
        if (s_.newlines) return ",\n  ";
        return s_.compact ? "," : ", ";
    }
    [[nodiscard]] std::string item_separator() const {
        if (s_.newlines) return ",\n    ";
        return s_.compact ? "," : ", ";
    }
    void open_list(std::size_t n) {
        out_ += "[";
        if (s_.newlines && n > 0) out_ += "\n    ";
    }
    void close_list(std::size_t n) {
        if (s_.newlines && n > 0) out_ += "\n  ";
        out_ += "]";
    }
    void number(double v) {
        Form f = Form::Shortest;
        switch (s_.numbers) {
            case Spelling::Numbers::Shortest: f = Form::Shortest; break;
            case Spelling::Numbers::Scientific: f = Form::Scientific; break;
            case Spelling::Numbers::ScientificPlus: f = Form::ScientificPlus; break;
            case Spelling::Numbers::Decimal: f = Form::Decimal; break;
            case Spelling::Numbers::Mixed: {
                // By the value, not the position: a graph shrunk from this one
                // writes each of its numbers the same way.
                std::uint64_t bits = 0;
                std::memcpy(&bits, &v, sizeof bits);
                f = static_cast<Form>(Rng(s_.seed ^ bits).below(5));
                break;
            }
        }
        out_ += spelled(v, f);
    }
    void vertices(const PlanarGraph& g) {
        open_list(g.vertices.size());
        for (std::size_t i = 0; i < g.vertices.size(); ++i) {
            if (i != 0) out_ += item_separator();
            out_ += "[";
            number(g.vertices[i].x);
            out_ += s_.compact ? "," : ", ";
            number(g.vertices[i].y);
            out_ += "]";
        }
        close_list(g.vertices.size());
    }
    void edges(const PlanarGraph& g) {
        open_list(g.edges.size());
        for (std::size_t i = 0; i < g.edges.size(); ++i) {
            if (i != 0) out_ += item_separator();
            out_ += "[" + std::to_string(g.edges[i].u.index()) + (s_.compact ? "," : ", ") +
                    std::to_string(g.edges[i].v.index()) + "]";
        }
        close_list(g.edges.size());
    }

    const Spelling& s_;
    std::string out_;
};

}  // namespace

Spelling Spelling::random(std::uint64_t seed, bool one_line) {
    Rng rng(seed);
    Spelling s;
    const std::uint64_t n = rng.below(20);
    s.numbers = n < 6    ? Numbers::Shortest
                : n < 9  ? Numbers::Scientific
                : n < 12 ? Numbers::ScientificPlus
                : n < 15 ? Numbers::Decimal
                         : Numbers::Mixed;
    s.positional = rng.chance(1, 5);
    s.edges_first = !s.positional && rng.chance(1, 3);
    s.compact = rng.chance(1, 3);
    s.newlines = !one_line && !s.compact && rng.chance(1, 4);
    s.seed = rng.next();
    return s;
}

std::string Spelling::describe() const {
    static constexpr const char* kNumbers[] = {"shortest numbers", "numbers like 3e0", "numbers like 3E+00",
                                               "integral numbers like 3.0", "numbers in mixed forms"};
    std::string d = kNumbers[static_cast<std::size_t>(numbers)];
    d += positional ? ", positional form" : (edges_first ? ", \"edges\" first" : ", object form");
    if (compact) d += ", no spaces";
    if (newlines) d += ", one item per line";
    return d;
}

std::string write_spelled(const PlanarGraph& g, const Spelling& s) { return Writer(s).write(g); }

}  // namespace dcel::gen
