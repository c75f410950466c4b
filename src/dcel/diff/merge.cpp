#include "dcel/diff/merge.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>

#include "dcel/diff/report.hpp"
#include "dcel/error.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::diff {
namespace {

using io::JsonType;

// ---- Building values.

JsonValue number(std::uint64_t n) { return {JsonType::Number, std::to_string(n), {}, {}}; }
JsonValue text(std::string s) { return {JsonType::String, std::move(s), {}, {}}; }
JsonValue null() { return {}; }
JsonValue boolean(bool b) { return {b ? JsonType::True : JsonType::False, {}, {}, {}}; }
JsonValue array(std::vector<JsonValue> items) { return {JsonType::Array, {}, std::move(items), {}}; }

void set(JsonValue& object, const std::string& key, JsonValue value) {
    for (auto& [k, v] : object.members) {
        if (k == key) {
            v = std::move(value);
            return;
        }
    }
    object.members.push_back({key, std::move(value)});
}

// ---- Reading a shard report, strictly: a field missing or of the wrong type
// is an error naming the file.

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw InvalidInput(InputErrorKind::Syntax, name + ": " + what);
}

const JsonValue& member(const ShardReport& s, const JsonValue& object, const std::string& key, JsonType type) {
    const JsonValue* v = object.find(key);
    if (v == nullptr) fail(s.name, "no \"" + key + "\": not a dcel diff report");
    const bool ok = v->type == type || (type == JsonType::True && v->type == JsonType::False);
    if (!ok) fail(s.name, "\"" + key + "\" has the wrong type");
    return *v;
}

std::uint64_t count_of(const ShardReport& s, const JsonValue& object, const std::string& key) {
    const std::optional<std::uint64_t> n = member(s, object, key, JsonType::Number).count();
    if (!n) fail(s.name, "\"" + key + "\" is not a count");
    return *n;
}

std::vector<std::uint64_t> counts_of(const ShardReport& s, const JsonValue& object, const std::string& key) {
    std::vector<std::uint64_t> out;
    for (const JsonValue& v : member(s, object, key, JsonType::Array).items) {
        const std::optional<std::uint64_t> n = v.count();
        if (!n) fail(s.name, "\"" + key + "\" holds something that is not a case number");
        out.push_back(*n);
    }
    return out;
}

// The command line without the words that differ between the shards of one
// campaign (--shard K/N, --jobs J).
std::string campaign_command(const ShardReport& s) {
    std::string command = member(s, s.report, "command", JsonType::String).text;
    for (const std::string option : {" --shard ", " --jobs "}) {
        const std::size_t at = command.find(option);
        if (at == std::string::npos) continue;
        const std::size_t end = command.find(' ', at + option.size());
        command.erase(at, end == std::string::npos ? std::string::npos : end - at);
    }
    return command;
}

struct ShardId {
    std::uint64_t index = 0, count = 0;
};

ShardId shard_of(const ShardReport& s) {
    const JsonValue* v = s.report.find("shard");
    if (v == nullptr || v->type != JsonType::String) {
        fail(s.name, "not the report of a shard: run dcel diff with --shard K/N");
    }
    // Digits, a slash, digits, nothing else: what dcel diff writes.
    const std::string& t = v->text;
    const std::size_t slash = t.find('/');
    ShardId id;
    const char* end = t.data() + t.size();
    const auto k = std::from_chars(t.data(), t.data() + std::min(slash, t.size()), id.index);
    const bool k_whole = slash != std::string::npos && k.ec == std::errc() && k.ptr == t.data() + slash;
    const auto n = k_whole ? std::from_chars(t.data() + slash + 1, end, id.count) : k;
    if (!k_whole || n.ec != std::errc() || n.ptr != end || id.index < 1 || id.index > id.count) {
        fail(s.name, "\"shard\" is not K/N");
    }
    return id;
}

// Every shard is of the same campaign, each once, none missing.
void check_campaign(const std::vector<ShardReport>& shards) {
    if (shards.empty()) throw InvalidInput(InputErrorKind::Syntax, "no reports to merge");
    const ShardId first = shard_of(shards[0]);
    const std::string command = campaign_command(shards[0]);
    std::map<std::uint64_t, std::string> seen;
    for (const ShardReport& s : shards) {
        if (member(s, s.report, "format", JsonType::String).text != "dcel diff report 1") {
            fail(s.name, "not a dcel diff report (\"format\" is not \"dcel diff report 1\")");
        }
        const ShardId id = shard_of(s);
        if (id.count != first.count) {
            fail(s.name, "a shard of " + std::to_string(id.count) + ", but " + shards[0].name + " is a shard of " +
                             std::to_string(first.count));
        }
        if (campaign_command(s) != command) {
            fail(s.name,
                 "another campaign than " + shards[0].name + ": the command lines differ besides --shard and --jobs");
        }
        if (const auto [it, fresh] = seen.emplace(id.index, s.name); !fresh) {
            fail(s.name,
                 "shard " + std::to_string(id.index) + "/" + std::to_string(id.count) + " again (also " + it->second + ")");
        }
    }
    for (std::uint64_t k = 1; k <= first.count; ++k) {
        if (!seen.contains(k)) {
            throw InvalidInput(InputErrorKind::Syntax, "shard " + std::to_string(k) + "/" + std::to_string(first.count) +
                                                           " is missing: give all " + std::to_string(first.count) +
                                                           " shard reports");
        }
    }
}

// ---- The run's figures.

std::uint64_t sum(const std::vector<ShardReport>& shards, const std::string& key) {
    std::uint64_t total = 0;
    for (const ShardReport& s : shards) total += count_of(s, s.report, key);
    return total;
}

JsonValue merged_skip_reasons(const std::vector<ShardReport>& shards) {
    std::vector<std::pair<std::string, std::uint64_t>> reasons;  // in the order first seen, shard by shard
    for (const ShardReport& s : shards) {
        for (const JsonValue& r : member(s, s.report, "skip_reasons", JsonType::Array).items) {
            const std::string reason = member(s, r, "reason", JsonType::String).text;
            const std::uint64_t n = count_of(s, r, "cases");
            auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto& p) { return p.first == reason; });
            if (it == reasons.end()) {
                reasons.emplace_back(reason, n);
            } else {
                it->second += n;
            }
        }
    }
    std::vector<JsonValue> items;
    for (const auto& [reason, n] : reasons) {
        JsonValue o{JsonType::Object, {}, {}, {}};
        set(o, "reason", text(reason));
        set(o, "cases", number(n));
        items.push_back(std::move(o));
    }
    return array(std::move(items));
}

// Sessions: the query steps skipped, by operation, summed over the shards.
JsonValue merged_skipped_steps(const std::vector<ShardReport>& shards) {
    std::vector<std::pair<std::string, std::uint64_t>> ops;  // in the order first seen
    for (const ShardReport& s : shards) {
        const JsonValue& skipped = member(s, s.report, "skipped_steps", JsonType::Object);
        for (const JsonValue::Member& m : skipped.members) {
            const std::string& op = m.key;
            const std::uint64_t n = count_of(s, skipped, op);
            auto it = std::find_if(ops.begin(), ops.end(), [&](const auto& p) { return p.first == op; });
            if (it == ops.end()) {
                ops.emplace_back(op, n);
            } else {
                it->second += n;
            }
        }
    }
    JsonValue out{JsonType::Object, {}, {}, {}};
    for (const auto& [op, n] : ops) set(out, op, number(n));
    return out;
}

JsonValue merged_slow(const std::vector<ShardReport>& shards) {
    std::uint64_t total = 0;
    std::vector<std::pair<std::uint64_t, JsonValue>> cases;
    for (const ShardReport& s : shards) {
        const JsonValue& slow = member(s, s.report, "slow", JsonType::Object);
        total += count_of(s, slow, "count");
        for (const JsonValue& c : member(s, slow, "cases", JsonType::Array).items) {
            cases.emplace_back(count_of(s, c, "number"), c);
        }
    }
    std::stable_sort(cases.begin(), cases.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (cases.size() > kMaxListedSlowCases) cases.resize(kMaxListedSlowCases);
    JsonValue o{JsonType::Object, {}, {}, {}};
    set(o, "count", number(total));
    std::vector<JsonValue> items;
    items.reserve(cases.size());
    for (auto& c : cases) items.push_back(std::move(c.second));
    set(o, "cases", array(std::move(items)));
    return o;
}

// ---- The failures, grouped as one run would group them.

// One key as one shard saw it.
struct KeyInShard {
    const ShardReport* shard = nullptr;
    const JsonValue* failure = nullptr;  // the shard's failure it was counted as
    bool founds = false;                 // the key that made that failure
    std::uint64_t occurrences = 0;
    std::vector<std::uint64_t> cases;
};

// A key over all shards.
struct Key {
    std::string key;
    std::string coordinates;  // its coordinate class (a part of the key)
    std::vector<KeyInShard> seen;
    [[nodiscard]] std::uint64_t first_case() const {
        std::uint64_t first = UINT64_MAX;
        for (const KeyInShard& k : seen) first = std::min(first, k.cases.front());
        return first;
    }
    // Where its first case was: that shard shrank it.
    [[nodiscard]] const KeyInShard& first_seen() const {
        return *std::min_element(seen.begin(), seen.end(),
                                 [](const KeyInShard& a, const KeyInShard& b) { return a.cases.front() < b.cases.front(); });
    }
};

std::vector<Key> keys_of(const std::vector<ShardReport>& shards) {
    std::vector<Key> keys;
    for (const ShardReport& s : shards) {
        for (const JsonValue& f : member(s, s.report, "failures", JsonType::Array).items) {
            bool first = true;
            for (const JsonValue& k : member(s, f, "keys", JsonType::Array).items) {
                KeyInShard in{&s, &f, first, count_of(s, k, "occurrences"), counts_of(s, k, "cases")};
                first = false;
                if (in.cases.empty()) fail(s.name, "a key with no cases");
                const std::string& name = member(s, k, "key", JsonType::String).text;
                auto it = std::find_if(keys.begin(), keys.end(), [&](const Key& x) { return x.key == name; });
                if (it == keys.end()) {
                    keys.push_back({name, member(s, k, "coordinates", JsonType::String).text, {}});
                    it = keys.end() - 1;
                }
                it->seen.push_back(std::move(in));
            }
        }
    }
    std::stable_sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.first_case() < b.first_case(); });
    return keys;
}

// The first kMaxListedCases of the union, in order.
std::vector<std::uint64_t> first_cases(const std::set<std::uint64_t>& all) {
    std::vector<std::uint64_t> out(all.begin(), all.end());
    if (out.size() > kMaxListedCases) out.resize(kMaxListedCases);
    return out;
}

JsonValue case_list(const std::vector<std::uint64_t>& cases) {
    std::vector<JsonValue> items;
    items.reserve(cases.size());
    for (const std::uint64_t n : cases) items.push_back(number(n));
    return array(std::move(items));
}

struct Merged {
    JsonValue failure;  // the founding shard's failure, its counts replaced
    std::vector<JsonValue> keys;
    std::vector<std::string> classes;
    std::set<std::uint64_t> cases;
    std::uint64_t occurrences = 0;
};

void add_key(Merged& m, const Key& k) {
    std::set<std::uint64_t> cases;
    std::uint64_t occurrences = 0;
    for (const KeyInShard& in : k.seen) {
        cases.insert(in.cases.begin(), in.cases.end());
        occurrences += in.occurrences;
    }
    const std::string& coordinates = k.coordinates;
    JsonValue record{JsonType::Object, {}, {}, {}};
    set(record, "key", text(k.key));
    set(record, "coordinates", text(coordinates));
    set(record, "occurrences", number(occurrences));
    set(record, "cases", case_list(first_cases(cases)));
    m.keys.push_back(std::move(record));
    if (std::find(m.classes.begin(), m.classes.end(), coordinates) == m.classes.end()) m.classes.push_back(coordinates);
    m.cases.insert(cases.begin(), cases.end());
    m.occurrences += occurrences;
}

JsonValue merged_failures(const std::vector<ShardReport>& shards) {
    std::vector<Merged> failures;
    for (const Key& k : keys_of(shards)) {
        const KeyInShard& first = k.first_seen();
        const std::string& signature = member(*first.shard, *first.failure, "signature", JsonType::String).text;
        auto it = std::find_if(failures.begin(), failures.end(),
                               [&](const Merged& m) { return m.failure.find("signature")->text == signature; });
        if (it == failures.end()) {
            if (!first.founds) {
                fail(first.shard->name,
                     "key \"" + k.key + "\" comes first in this shard but joined a failure found before it");
            }
            failures.push_back({*first.failure, {}, {}, {}, 0});
            it = failures.end() - 1;
        }
        add_key(*it, k);
    }
    std::vector<JsonValue> out;
    for (std::size_t i = 0; i < failures.size(); ++i) {
        Merged& m = failures[i];
        set(m.failure, "id", number(i + 1));
        std::vector<JsonValue> classes;
        for (const std::string& c : m.classes) classes.push_back(text(c));
        set(m.failure, "classes", array(std::move(classes)));
        set(m.failure, "occurrences", number(m.occurrences));
        set(m.failure, "cases", case_list(first_cases(m.cases)));
        set(m.failure, "keys", array(std::move(m.keys)));
        out.push_back(std::move(m.failure));
    }
    return array(std::move(out));
}

// The report's members in the order dcel diff writes them.
JsonValue merged_run(const std::vector<ShardReport>& shards, JsonValue failures) {
    const ShardReport& s0 = shards[0];
    JsonValue out{JsonType::Object, {}, {}, {}};
    set(out, "format", text("dcel diff report 1"));
    set(out, "command", text(campaign_command(s0)));
    set(out, "impl", member(s0, s0.report, "impl", JsonType::String));
    set(out, "seed", member(s0, s0.report, "seed", JsonType::Number));
    if (const JsonValue* sessions = s0.report.find("sessions"); sessions != nullptr && sessions->type == JsonType::True) {
        set(out, "sessions", boolean(true));
        set(out, "cycles_only_sessions", number(sum(shards, "cycles_only_sessions")));
        set(out, "skipped_steps", merged_skipped_steps(shards));
    }
    set(out, "shard", null());
    set(out, "shards", number(shards.size()));
    const JsonValue* kind = s0.report.find("answer_kind");
    set(out, "answer_kind", kind != nullptr ? *kind : null());
    set(out, "conventions", member(s0, s0.report, "conventions", JsonType::Object));
    set(out, "cases_run", number(sum(shards, "cases_run")));
    std::uint64_t first = UINT64_MAX;
    for (const ShardReport& s : shards) first = std::min(first, count_of(s, s.report, "first_case"));
    set(out, "first_case", number(first));
    set(out, "skipped", number(sum(shards, "skipped")));
    set(out, "skipped_by_impl", number(sum(shards, "skipped_by_impl")));
    set(out, "skip_reasons", merged_skip_reasons(shards));
    const std::uint64_t checked = sum(shards, "checked");
    set(out, "checked", number(checked));
    set(out, "slow", merged_slow(shards));
    set(out, "large_cases", number(sum(shards, "large_cases")));
    // "cases" when every shard ran all its cases; otherwise what stopped the first that did not.
    std::string stopped = "cases";
    std::uint64_t elapsed = 0;
    for (const ShardReport& s : shards) {
        const std::string& why = member(s, s.report, "stopped_by", JsonType::String).text;
        if (stopped == "cases") stopped = why;
        elapsed = std::max(elapsed, count_of(s, s.report, "elapsed_ms"));  // the shards run side by side
    }
    set(out, "stopped_by", text(stopped));
    set(out, "elapsed_ms", number(elapsed));
    set(out, "reference_cpu_ms", number(sum(shards, "reference_cpu_ms")));
    set(out, "agrees", boolean(failures.items.empty() && checked > 0));
    set(out, "failures", std::move(failures));
    return out;
}

// Recursion: as deep as the document, which the reader bounded.
void write_value(io::JsonWriter& w, const JsonValue& v, int depth) {  // NOLINT(misc-no-recursion)
    using Layout = io::JsonWriter::Layout;
    const Layout layout = depth < 2 ? Layout::Lines : Layout::Inline;
    switch (v.type) {
        case JsonType::Null: w.null(); break;
        case JsonType::True: w.boolean(true); break;
        case JsonType::False: w.boolean(false); break;
        case JsonType::Number: w.raw(std::string_view(v.text)); break;
        case JsonType::String: w.string(v.text); break;
        case JsonType::Array:
            w.begin_array(layout);
            for (const JsonValue& item : v.items) {
                w.item();
                write_value(w, item, depth + 1);
            }
            w.end_array();
            break;
        case JsonType::Object:
            w.begin_object(layout);
            for (const auto& [key, value] : v.members) {
                w.key(key);
                write_value(w, value, depth + 1);
            }
            w.end_object();
            break;
    }
}

std::string str(const JsonValue& object, const std::string& key) {
    const JsonValue* v = object.find(key);
    return v != nullptr ? v->string_or() : std::string();
}
std::uint64_t num(const JsonValue& object, const std::string& key) {
    const JsonValue* v = object.find(key);
    return v != nullptr ? v->count().value_or(0) : 0;
}

std::string classes_text(const JsonValue& failure) {
    std::string s;
    const JsonValue* classes = failure.find("classes");
    const std::size_t n = classes != nullptr ? classes->items.size() : 0;
    for (std::size_t i = 0; i < n; ++i) {
        s += i == 0 ? "" : (i + 1 == n ? " and " : ", ");
        s += classes->items[i].string_or();
    }
    return s + " coordinates";
}

std::string shrunk_size(const JsonValue& failure) {
    const JsonValue* c = failure.find("counterexample");
    return c == nullptr ? "?" : size_of(num(*c, "vertices"), num(*c, "edges"));
}

}  // namespace

JsonValue merge_reports(const std::vector<ShardReport>& shards) {
    check_campaign(shards);
    return merged_run(shards, merged_failures(shards));
}

std::string write_json(const JsonValue& value) {
    std::string out;
    io::JsonWriter w(out);
    write_value(w, value, 0);
    w.flush();
    out += '\n';
    return out;
}

// What went unchecked in a merged session run, as dcel diff says it.
void session_warnings(std::ostream& s, const JsonValue& merged) {
    if (merged.find("sessions") == nullptr) return;
    if (const std::uint64_t n = num(merged, "cycles_only_sessions"); n > 0) {
        s << "warning: " << count(n, "session")
          << " gave the state as boundary cycles only: where holes and isolated vertices lie went unchecked\n";
    }
    const JsonValue* skipped = merged.find("skipped_steps");
    if (skipped == nullptr || skipped->members.empty()) return;
    std::uint64_t total = 0;
    std::string ops;
    for (const JsonValue::Member& m : skipped->members) {
        total += num(*skipped, m.key);
        ops += (ops.empty() ? "" : ", ") + std::to_string(num(*skipped, m.key)) + " " + m.key;
    }
    s << "warning: the answers skipped " << count(total, "query step") << " ({\"skip\": ...}): " << ops
      << "; they went unchecked\n";
}

std::string merged_summary(const JsonValue& merged) {
    std::ostringstream s;
    const JsonValue* failures = merged.find("failures");
    const std::size_t n = failures != nullptr ? failures->items.size() : 0;
    const std::string cases = count(num(merged, "cases_run"), "case");
    const std::string from = count(num(merged, "shards"), "shard") + ", seed " + std::to_string(num(merged, "seed"));
    if (n == 0) {
        s << "dcel diff-merge: " << (num(merged, "checked") > 0 ? "agrees on " : "nothing checked in ") << cases << " ("
          << from << ")\n";
        session_warnings(s, merged);
        return s.str();
    }
    s << "dcel diff-merge: " << count(n, "distinct failure") << " in " << cases << " (" << from << ")\n";
    for (const JsonValue& f : failures->items) {
        const JsonValue* outcome = f.find("outcome");  // on the counterexample, as dcel diff's summary says it
        s << "  " << num(f, "id") << ". " << (outcome != nullptr ? str(*outcome, "label") : str(f, "label")) << ": "
          << count(num(f, "occurrences"), "case") << " in " << classes_text(f) << ", shrunk to " << shrunk_size(f) << "\n";
        s << "     replay: " << str(f, "replay") << "\n";
    }
    session_warnings(s, merged);
    return s.str();
}

std::string merged_junit(const JsonValue& merged) {
    std::ostringstream s;
    const JsonValue* failures = merged.find("failures");
    const std::size_t n = failures != nullptr ? failures->items.size() : 0;
    s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s << "<testsuites name=\"dcel diff\" tests=\"" << n + 1 << "\" failures=\"" << n << "\">\n";
    s << "  <testsuite name=\"" << xml_text("dcel diff --impl " + str(merged, "impl")) << "\" tests=\"" << n + 1
      << "\" failures=\"" << n << "\" time=\"" << static_cast<double>(num(merged, "elapsed_ms")) / 1000.0 << "\">\n";
    s << "    <testcase classname=\"dcel.diff\" name=\"" << (num(merged, "cases_run") - num(merged, "skipped"))
      << " cases, seed " << num(merged, "seed") << ", " << count(num(merged, "shards"), "shard") << "\"/>\n";
    for (std::size_t i = 0; i < n; ++i) {
        const JsonValue& f = failures->items[i];
        const JsonValue* c = f.find("counterexample");
        const JsonValue* outcome = f.find("outcome");
        std::ostringstream body;
        body << "counterexample: " << shrunk_size(f) << "\n";
        if (c != nullptr) body << "graph:\n  " << without_newline(str(*c, "text")) << "\n";
        body << "reference:\n  " << str(f, "reference") << "\n";
        if (outcome != nullptr) {
            body << "the command says (" << str(*outcome, "label") << "):\n  " << str(*outcome, "stdout") << "\n";
            if (const JsonValue* d = outcome->find("differences"); d != nullptr) {
                for (const JsonValue& diff : d->items)
                    body << "[" << str(diff, "kind") << "] " << str(diff, "message") << "\n";
            }
        }
        body << "replay the case:\n  " << str(f, "replay") << "\n";
        s << "    <testcase classname=\"dcel.diff\" name=\""
          << xml_text("failure " + std::to_string(num(f, "id")) + ": " + str(f, "signature")) << "\">\n";
        s << "      <failure message=\"" << xml_text(str(f, "label") + ", shrunk to " + shrunk_size(f)) << "\" type=\""
          << xml_text(str(f, "kind")) << "\">" << xml_text(body.str()) << "</failure>\n";
        s << "    </testcase>\n";
    }
    s << "  </testsuite>\n</testsuites>\n";
    return s.str();
}

}  // namespace dcel::diff
