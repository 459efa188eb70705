// A small JSON reader for tests that parse the CLI's output back (RFC 8259 values; numbers as
// double; no \u escapes beyond ASCII). Throws std::runtime_error on malformed input, so a test
// fails when the output is not valid JSON.
#pragma once
#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace qt::test {

struct Json {
    enum class Type { null, boolean, number, string, array, object } type = Type::null;
    bool b = false;
    double num = 0;
    std::string str;
    std::vector<Json> items;
    std::map<std::string, Json> fields;

    const Json& operator[](const std::string& key) const {
        if (type != Type::object) throw std::runtime_error("not an object looking up " + key);
        auto it = fields.find(key);
        if (it == fields.end()) throw std::runtime_error("missing key " + key);
        return it->second;
    }
    const Json& operator[](size_t i) const {
        if (type != Type::array || i >= items.size()) throw std::runtime_error("bad array index");
        return items[i];
    }
    bool has(const std::string& key) const { return type == Type::object && fields.count(key) > 0; }
};

class JsonReader {
public:
    static Json parse(const std::string& text) {
        JsonReader r(text);
        Json v = r.value();
        r.skip();
        if (r.pos_ != text.size()) throw std::runtime_error("trailing characters");
        return v;
    }

private:
    explicit JsonReader(const std::string& t) : t_(t) {}
    void skip() {
        while (pos_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[pos_]))) ++pos_;
    }
    char peek() {
        skip();
        if (pos_ >= t_.size()) throw std::runtime_error("unexpected end");
        return t_[pos_];
    }
    void expect(char c) {
        if (peek() != c)
            throw std::runtime_error(std::string("expected ") + c + " at " + std::to_string(pos_));
        ++pos_;
    }
    void literal(const char* word) {
        for (const char* p = word; *p; ++p, ++pos_)
            if (pos_ >= t_.size() || t_[pos_] != *p) throw std::runtime_error("bad literal");
    }
    std::string string() {
        expect('"');
        std::string s;
        while (pos_ < t_.size() && t_[pos_] != '"') {
            if (t_[pos_] == '\\') {
                ++pos_;
                if (pos_ >= t_.size()) break;
                const char e = t_[pos_];
                s += e == 'n' ? '\n' : e == 't' ? '\t' : e;
            } else {
                if (static_cast<unsigned char>(t_[pos_]) < 0x20)
                    throw std::runtime_error("control char in string");
                s += t_[pos_];
            }
            ++pos_;
        }
        expect('"');
        return s;
    }
    Json value() {
        Json v;
        const char c = peek();
        if (c == '{') {
            v.type = Json::Type::object;
            ++pos_;
            if (peek() == '}') {
                ++pos_;
                return v;
            }
            for (;;) {
                std::string key = string();
                expect(':');
                v.fields[key] = value();
                if (peek() == ',') {
                    ++pos_;
                    continue;
                }
                expect('}');
                return v;
            }
        }
        if (c == '[') {
            v.type = Json::Type::array;
            ++pos_;
            if (peek() == ']') {
                ++pos_;
                return v;
            }
            for (;;) {
                v.items.push_back(value());
                if (peek() == ',') {
                    ++pos_;
                    continue;
                }
                expect(']');
                return v;
            }
        }
        if (c == '"') {
            v.type = Json::Type::string;
            v.str = string();
            return v;
        }
        if (c == 'n') {
            literal("null");
            return v;
        }
        if (c == 't' || c == 'f') {
            v.type = Json::Type::boolean;
            v.b = c == 't';
            literal(v.b ? "true" : "false");
            return v;
        }
        // Number per RFC 8259: -? int frac? exp?
        const size_t start = pos_;
        if (t_[pos_] == '-') ++pos_;
        if (pos_ >= t_.size() || !std::isdigit(static_cast<unsigned char>(t_[pos_])))
            throw std::runtime_error("bad value");
        while (pos_ < t_.size() &&
               (std::isdigit(static_cast<unsigned char>(t_[pos_])) || t_[pos_] == '.' ||
                t_[pos_] == 'e' || t_[pos_] == 'E' || t_[pos_] == '+' || t_[pos_] == '-'))
            ++pos_;
        const std::string num = t_.substr(start, pos_ - start);
        char* end = nullptr;
        v.type = Json::Type::number;
        v.num = std::strtod(num.c_str(), &end);
        if (*end != '\0') throw std::runtime_error("bad number " + num);
        return v;
    }

    const std::string& t_;
    size_t pos_ = 0;
};

}  // namespace qt::test
