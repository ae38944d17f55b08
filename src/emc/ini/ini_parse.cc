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

const size_t max_include_depth = 16;              // files open at once, the top file included
const off_t max_file_bytes = 64 * 1024 * 1024;    // larger files (or endless devices) are refused
const char utf8_bom[] = "\xEF\xBB\xBF";

// "errno=N (text)" as used in file errors.
std::string errno_text(int err)
{
    return "errno=" + std::to_string(err) + " (" + strerror(err) + ")";
}

// Read a whole file (at most max_file_bytes); false after printing "<path>: error: ...".
bool read_file(const std::string &path, std::string &text)
{
    int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        fprintf(stderr, "%s: error: Cannot open ini-file (%s)\n", path.c_str(), errno_text(errno).c_str());
        return false;
    }
    char buf[65536];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) != 0) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        text.append(buf, size_t(n));
        if (text.size() > size_t(max_file_bytes)) break;
    }
    int saved = errno;
    close(fd);
    if (n < 0) {
        fprintf(stderr, "%s: error: Cannot read ini-file (%s)\n", path.c_str(), errno_text(saved).c_str());
        return false;
    }
    if (text.size() > size_t(max_file_bytes)) {
        fprintf(stderr, "%s: error: Ini-file is larger than %lld bytes\n", path.c_str(),
                (long long)max_file_bytes);
        return false;
    }
    if (text.compare(0, 3, utf8_bom) == 0) text.erase(0, 3);
    return true;
}

// How CheckName words its messages about a section or a tag name.
struct NameWords {
    const char *bad_chars;   // "Invalid <bad_chars> 'x'. Identifier contains invalid character(s)"
    const char *digit;       // "Invalid <digit> 'x'. <digit_tail>"
    const char *digit_tail;
};
const NameWords section_words = {"section", "section", "Cannot start with a digit"};
const NameWords tag_words = {"tag name", "tag", "Tag identifiers cannot start with a digit"};

// True for the blanks that separate words on a line.
bool is_space(char c)
{
    return c == ' ' || c == '\t';
}

} // namespace

// Parses one file (and its includes) into an IniFile; stops at the first error.
class IniParser {
public:
    explicit IniParser(IniFile &ini) : ini_(ini) {}
    // Parse a file; false when it could not be read or had a syntax error (reported on stderr).
    bool ParseFile(const std::string &path);

private:
    bool Report(const std::string &file, int line, const char *level, const std::string &what);
    bool ParseText(const std::string &file, const std::string &text);
    bool HandleLine(const std::string &file, int line, const std::string &text);
    bool HandleSection(const std::string &file, int line, const std::string &text);
    bool HandleKey(const std::string &file, int line, const std::string &text);
    bool HandleInclude(const std::string &file, int line, const std::string &text);
    bool CheckName(const std::string &file, int line, const std::string &name, const NameWords &words);

    IniFile &ini_;
    int current_ = -1;                 // index of the current section, -1 before the first
    std::vector<std::string> stack_;   // canonical paths of the files being parsed
};

// Print "<file>:<line>: <level>: <what>"; returns true for warnings, false for errors.
bool IniParser::Report(const std::string &file, int line, const char *level, const std::string &what)
{
    fprintf(stderr, "%s:%d: %s: %s\n", file.c_str(), line, level, what.c_str());
    return strcmp(level, "error") != 0;
}

// Read and parse one file, keeping it on the include stack meanwhile.
bool IniParser::ParseFile(const std::string &path)
{
    std::string text;
    if (!read_file(path, text)) return false;
    char *canon = realpath(path.c_str(), nullptr);
    stack_.push_back(canon ? canon : path);
    free(canon);
    bool ok = ParseText(path, text);
    stack_.pop_back();
    return ok;
}

// Split text into logical lines (a trailing '\' joins the next line) and handle each. A
// continued line is numbered by its last physical line.
bool IniParser::ParseText(const std::string &file, const std::string &text)
{
    std::string logical;
    int line = 0;
    for (size_t start = 0; start < text.size();) {
        size_t nl = text.find('\n', start);
        bool last = nl == std::string::npos || nl + 1 == text.size();
        if (nl == std::string::npos) nl = text.size();
        std::string physical = ini_rtrim(text.substr(start, nl - start));
        start = nl + 1;
        line++;
        bool continued = !physical.empty() && physical.back() == '\\';
        if (continued) physical.pop_back();
        logical += physical;
        if (continued && last) return Report(file, line, "error", "Last line has a continuation");
        if (continued) continue;
        if (!HandleLine(file, line, logical)) return false;
        logical.clear();
    }
    return true;
}

// Classify one logical line: include, blank, comment, section header or key.
bool IniParser::HandleLine(const std::string &file, int line, const std::string &text)
{
    if (text.find('\0') != std::string::npos)
        return Report(file, line, "error", "Embedded literal NUL character not supported");
    if (text.compare(0, 8, "#INCLUDE") == 0) return HandleInclude(file, line, text);
    size_t start = text.find_first_not_of(" \t\r\n\v\f");
    if (start == std::string::npos || text[start] == '#' || text[start] == ';') return true;
    std::string body = text.substr(start);
    return body[0] == '[' ? HandleSection(file, line, body) : HandleKey(file, line, body);
}

// Check a section or tag name: identifier characters first, then no leading digit.
bool IniParser::CheckName(const std::string &file, int line, const std::string &name,
                          const NameWords &words)
{
    if (!ini_identifier_chars(name))
        return Report(file, line, "error", std::string("Invalid ") + words.bad_chars + " '" + name +
                                               "'. Identifier contains invalid character(s)");
    if (name[0] >= '0' && name[0] <= '9')
        return Report(file, line, "error", std::string("Invalid ") + words.digit + " '" + name +
                                               "'. " + words.digit_tail);
    return true;
}

// "[NAME] trailing": start or resume a section.
bool IniParser::HandleSection(const std::string &file, int line, const std::string &text)
{
    size_t close = text.find(']');
    if (close == std::string::npos) return Report(file, line, "error", "Invalid section. Missing ']'");
    std::string name = ini_trim(text.substr(1, close - 1));
    if (name.empty())
        return Report(file, line, "error", "Invalid section. No content between '[' and ']'");
    if (!CheckName(file, line, name, section_words)) return false;
    current_ = -1;
    for (size_t i = 0; i < ini_.sections_.size() && current_ < 0; i++) {
        if (ini_.sections_[i].name != name) continue;
        Report(file, line, "warning", "Section '" + name + "' already exists. Merging...");
        current_ = int(i);
    }
    if (current_ < 0) {
        ini_.sections_.push_back(IniSection{name, {}});
        current_ = int(ini_.sections_.size() - 1);
    }
    std::string rest = ini_trim(text.substr(close + 1));
    if (!rest.empty() && rest[0] != '#' && rest[0] != ';')
        Report(file, line, "warning", "Section header has trailing content, ignored");
    return true;
}

// "KEY = value": add an entry to the current section.
bool IniParser::HandleKey(const std::string &file, int line, const std::string &text)
{
    size_t eq = text.find('=');
    if (eq == std::string::npos)
        return Report(file, line, "error", "Invalid tag '" + text + "'. Expected '=' after tag identifier");
    if (eq == 0) return Report(file, line, "error", "Invalid tag. Missing identifier before '='");
    std::string tag = ini_rtrim(text.substr(0, eq));
    if (!CheckName(file, line, tag, tag_words)) return false;
    if (current_ < 0)
        return Report(file, line, "error", "Tag '" + tag + "' found without prior section definition");
    std::string value, error;
    std::vector<std::string> warnings;
    bool decoded = ini_decode_escapes(ini_trim(text.substr(eq + 1)), value, warnings, error);
    for (const std::string &w : warnings) Report(file, line, "warning", w);
    if (!decoded) return Report(file, line, "error", error);
    IniSection &sec = ini_.sections_[size_t(current_)];
    sec.entries.push_back(IniEntry{tag, value, sec.name, file, line});
    return true;
}

// "#INCLUDE name": parse another file in place, continuing the current section. A relative
// name is taken relative to the including file's directory.
bool IniParser::HandleInclude(const std::string &file, int line, const std::string &text)
{
    if (text.size() <= 8 || !is_space(text[8]))
        return Report(file, line, "error", "Missing filename after #INCLUDE");
    std::string name = ini_trim(text.substr(8));
    std::string path = IniFile::TildeExpand(name);
    if (path.compare(0, 2, "~/") == 0)
        return Report(file, line, "error", "Failed to tilde-expand '" + name + "'");
    size_t slash = file.rfind('/');
    if (path[0] != '/' && slash != std::string::npos) path = file.substr(0, slash + 1) + path;
    char *canon = realpath(path.c_str(), nullptr);
    std::string key = canon ? canon : path;
    free(canon);
    for (const std::string &open_file : stack_)
        if (open_file == key)
            return Report(file, line, "error", "Include file recursion on loading '" + path + "'");
    if (stack_.size() + 1 >= max_include_depth)
        return Report(file, line, "error", "Maximum include depth (" + std::to_string(max_include_depth) +
                                               ") reached on loading '" + path + "'");
    return ParseFile(path);
}

// Parse `path` into this object (see inifile.hh).
bool IniFile::Open(const std::string &path)
{
    Close();
    path_ = path;
    IniParser parser(*this);
    if (!parser.ParseFile(path)) {
        error_ = "Cannot load ini-file '" + path + "'";
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
