// ini_parse.cc: the INI file parser (lines, continuations, sections, keys, #INCLUDE) behind IniFile::Open.
#include "inifile.hh"
#include "ini_text.hh"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace {

const int max_include_depth = 16;

// Read a whole file; false with errno set when it cannot be read.
bool read_file(const std::string &path, std::string &text)
{
    int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    char buf[65536];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) > 0) text.append(buf, size_t(n));
    int saved = errno;
    close(fd);
    errno = saved;
    return n == 0;
}

// "errno=N (text)" as used in open failures.
std::string errno_text(int err)
{
    return "errno=" + std::to_string(err) + " (" + strerror(err) + ")";
}

// Directory part of a path, with the trailing slash ("" for a bare name).
std::string dir_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

} // namespace

// Parses one file (and its includes) into an IniFile.
class IniParser {
public:
    explicit IniParser(IniFile &ini) : ini_(ini) {}
    // Parse a file; false when it could not be read or had a syntax error.
    bool ParseFile(const std::string &path, int depth);
    // True when no error was reported.
    bool Ok() const { return ok_; }

private:
    void Report(const std::string &file, int line, const char *level, const std::string &what);
    void HandleLine(const std::string &file, int line, const std::string &text, int depth);
    void HandleSection(const std::string &file, int line, const std::string &text);
    void HandleKey(const std::string &file, int line, const std::string &text);
    bool CheckName(const std::string &file, int line, const char *kind, const std::string &name,
                   const char *empty_error);
    void HandleInclude(const std::string &file, int line, const std::string &name, int depth);

    IniFile &ini_;
    int current_ = -1;                 // index of the current section, -1 none, -2 a bad header
    std::vector<std::string> stack_;   // canonical paths of the files being parsed
    bool ok_ = true;
};

// Print a diagnostic "<file>:<line>: <level>: <what>"; errors make the file unloadable.
void IniParser::Report(const std::string &file, int line, const char *level,
                       const std::string &what)
{
    fprintf(stderr, "%s:%d: %s: %s\n", file.c_str(), line, level, what.c_str());
    if (strcmp(level, "error") == 0) ok_ = false;
}

// Split a file into logical lines (continuations joined) and handle each.
bool IniParser::ParseFile(const std::string &path, int depth)
{
    std::string text;
    if (!read_file(path, text)) return false;
    char *canon = realpath(path.c_str(), nullptr);
    stack_.push_back(canon ? canon : path);
    free(canon);
    std::vector<std::string> lines;
    for (size_t start = 0; start < text.size();) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) nl = text.size();
        lines.push_back(ini_rtrim(text.substr(start, nl - start)));
        start = nl + 1;
    }
    for (size_t i = 0; i < lines.size(); i++) {
        size_t first = i;
        std::string logical = lines[i];
        while (!logical.empty() && logical.back() == '\\' && i + 1 < lines.size()) {
            logical.pop_back();
            logical += lines[++i];
        }
        if (!logical.empty() && logical.back() == '\\') {
            Report(path, int(i + 1), "error", "Last line has a continuation");
            break;
        }
        HandleLine(path, int(first + 1), logical, depth);
    }
    stack_.pop_back();
    return true;
}

// Classify one logical line: blank, include, comment, section header or key.
void IniParser::HandleLine(const std::string &file, int line, const std::string &text, int depth)
{
    if (text.find('\0') != std::string::npos) {
        Report(file, line, "error", "Line contains a NUL character");
        return;
    }
    if (text.compare(0, 8, "#INCLUDE") == 0 && text.size() > 8 &&
        (text[8] == ' ' || text[8] == '\t')) {
        HandleInclude(file, line, ini_trim(text.substr(8)), depth);
        return;
    }
    std::string body = ini_trim(text);
    if (body.empty() || body[0] == '#' || body[0] == ';') return;
    if (body[0] == '[')
        HandleSection(file, line, body);
    else
        HandleKey(file, line, body);
}

// Report an empty name (empty_error) or one that is not an identifier; true when it is usable.
bool IniParser::CheckName(const std::string &file, int line, const char *kind,
                          const std::string &name, const char *empty_error)
{
    if (name.empty()) {
        Report(file, line, "error", empty_error);
        return false;
    }
    if (!ini_valid_identifier(name)) {
        Report(file, line, "error", std::string("Invalid ") + kind + " '" + name +
                                        "'. Identifier contains invalid character(s)");
        return false;
    }
    return true;
}

// "[NAME] trailing": start or resume a section.
void IniParser::HandleSection(const std::string &file, int line, const std::string &text)
{
    current_ = -2;
    size_t close = text.find(']');
    if (close == std::string::npos) {
        Report(file, line, "error", "Invalid section. Missing ']'");
        return;
    }
    std::string name = ini_trim(text.substr(1, close - 1));
    if (!CheckName(file, line, "section", name,
                   "Invalid section. No content between '[' and ']'"))
        return;
    std::string rest = ini_trim(text.substr(close + 1));
    if (!rest.empty() && rest[0] != '#' && rest[0] != ';')
        Report(file, line, "warning", "Section header has trailing content, ignored");
    for (size_t i = 0; i < ini_.sections_.size(); i++) {
        if (ini_.sections_[i].name == name) {
            Report(file, line, "warning", "Section '" + name + "' already exists. Merging...");
            current_ = int(i);
            return;
        }
    }
    ini_.sections_.push_back(IniSection{name, {}});
    current_ = int(ini_.sections_.size() - 1);
}

// "KEY = value": add an entry to the current section.
void IniParser::HandleKey(const std::string &file, int line, const std::string &text)
{
    size_t end = text.find_first_of(" \t=");
    std::string tag = text.substr(0, end);
    if (!CheckName(file, line, "tag", tag, "Missing tag identifier before '='")) return;
    size_t eq = text.find_first_not_of(" \t", end);
    if (eq == std::string::npos || text[eq] != '=') {
        Report(file, line, "error", "Invalid tag '" + tag + "'. Expected '=' after tag identifier");
        return;
    }
    if (current_ == -2) return;  // the bad header was reported already
    if (current_ < 0) {
        Report(file, line, "error", "Tag '" + tag + "' found without prior section definition");
        return;
    }
    std::string value, error;
    std::vector<std::string> warnings;
    bool decoded = ini_decode_escapes(ini_trim(text.substr(eq + 1)), value, warnings, error);
    for (const std::string &w : warnings) Report(file, line, "warning", w);
    if (!decoded) {
        Report(file, line, "error", error);
        return;
    }
    IniSection &sec = ini_.sections_[size_t(current_)];
    sec.entries.push_back(IniEntry{tag, value, sec.name, file, line});
}

// "#INCLUDE name": parse another file in place, continuing the current section.
void IniParser::HandleInclude(const std::string &file, int line, const std::string &name,
                              int depth)
{
    std::string path = IniFile::TildeExpand(name);
    if (path[0] != '/') path = dir_of(file) + path;
    if (depth >= max_include_depth) {
        Report(file, line, "error", "Include nesting too deep on loading '" + path + "'");
        return;
    }
    char *canon = realpath(path.c_str(), nullptr);
    std::string key = canon ? canon : path;
    free(canon);
    for (const std::string &open_file : stack_) {
        if (open_file == key) {
            Report(file, line, "error", "Include file recursion on loading '" + path + "'");
            return;
        }
    }
    if (!ParseFile(path, depth + 1))
        Report(file, line, "error",
               "Cannot open include file '" + path + "' (" + errno_text(errno) + ")");
}

// Parse `path` into this object (see inifile.hh).
bool IniFile::Open(const std::string &path)
{
    Close();
    path_ = path;
    IniParser parser(*this);
    if (!parser.ParseFile(path, 0)) {
        error_ = "Cannot open ini-file (" + errno_text(errno) + ")";
        fprintf(stderr, "%s: error: %s\n", path.c_str(), error_.c_str());
        return false;
    }
    if (!parser.Ok()) {
        error_ = "Syntax error(s) in ini-file";
        sections_.clear();
        return false;
    }
    open_ = true;
    return true;
}

// Forget everything parsed.
void IniFile::Close()
{
    sections_.clear();
    error_.clear();
    open_ = false;
}
