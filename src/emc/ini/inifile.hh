// inifile.hh: C++ API of the INI library (parse once, then look up keys by section and occurrence).
#ifndef OPENEMC_INIFILE_HH
#define OPENEMC_INIFILE_HH

#include <optional>
#include <string>
#include <utility>
#include <vector>

// One KEY = value line as stored after parsing (escapes decoded, trimmed).
struct IniEntry {
    std::string key;
    std::string value;
    std::string section;  // name of the section holding the entry
    std::string file;  // file the line came from (an included file where relevant)
    int line = 0;      // 1-based line number of the (first physical) line
};

// One [SECTION] with its entries in file order (repeated headers merged).
struct IniSection {
    std::string name;
    std::vector<IniEntry> entries;
};

// A parsed INI file. Any syntax error makes the whole file unloadable.
class IniFile {
public:
    IniFile() = default;
    // Parse `path` at construction; check IsOpen() afterwards.
    explicit IniFile(const std::string &path) { Open(path); }

    // Parse `path`; diagnostics go to stderr; false when unreadable or on any syntax error.
    bool Open(const std::string &path);
    // Forget the parsed content.
    void Close();
    // True when the last Open() succeeded.
    bool IsOpen() const { return open_; }
    // Path given to the last Open().
    const std::string &Path() const { return path_; }
    // "Cannot load ini-file '<path>'" after a failed Open() (the details went to stderr), else empty.
    const std::string &ErrorText() const { return error_; }
    // Silence (true) or enable (false) diagnostics of typed lookups on stderr.
    void SetQuiet(bool quiet) { quiet_ = quiet; }

    // The num-th (1-based) value of key in section ("" = any section, counted across sections).
    std::optional<std::string> Find(const std::string &key, const std::string &section = "",
                                    int num = 1) const;
    // The entry behind Find() (value, file and line), or nullptr.
    const IniEntry *FindEntry(const std::string &key, const std::string &section = "",
                              int num = 1) const;
    // Signed integer (decimal or 0x/0o/0b prefix); nullopt when missing or invalid (diagnosed).
    std::optional<long long> FindInt(const std::string &key, const std::string &section = "",
                                     int num = 1) const;
    // Unsigned integer; a negative value wraps with a warning.
    std::optional<unsigned long long> FindUInt(const std::string &key,
                                               const std::string &section = "",
                                               int num = 1) const;
    // Real number (strtod in the C locale).
    std::optional<double> FindReal(const std::string &key, const std::string &section = "",
                                   int num = 1) const;
    // Strict boolean: TRUE YES ON 1 FALSE NO OFF 0, case-insensitive.
    std::optional<bool> FindBool(const std::string &key, const std::string &section = "",
                                 int num = 1) const;
    // LINEAR_UNITS enum as units per mm (mm/metric 1, in/inch/imperial 1/25.4).
    std::optional<double> FindLinearUnits(const std::string &key, const std::string &section = "",
                                          int num = 1) const;
    // ANGULAR_UNITS enum as units per degree (deg/degree 1, rad/radian pi/180, grad/gon 0.9).
    std::optional<double> FindAngularUnits(const std::string &key,
                                           const std::string &section = "", int num = 1) const;
    // Joint TYPE enum: LINEAR 1, ANGULAR 2.
    std::optional<int> FindJointType(const std::string &key, const std::string &section = "",
                                     int num = 1) const;

    // Every value of key in section ("" = all sections), in file order.
    std::vector<std::string> FindAll(const std::string &key, const std::string &section = "") const;
    // True when the section exists.
    bool HasSection(const std::string &section) const;
    // Section names in file order (included files' sections too).
    std::vector<std::string> Sections() const;
    // (key, value) pairs of a section ("" = all sections), duplicates kept, in file order.
    std::vector<std::pair<std::string, std::string>> Variables(const std::string &section = "") const;
    // All parsed sections (read-only).
    const std::vector<IniSection> &AllSections() const { return sections_; }

    // Map enum strings (case-insensitive); nullopt when unknown.
    static std::optional<double> MapLinearUnits(const std::string &text);
    static std::optional<double> MapAngularUnits(const std::string &text);
    static std::optional<int> MapJointType(const std::string &text);
    // Turn a leading "~/" into $HOME/ (unchanged when HOME is not set).
    static std::string TildeExpand(const std::string &path);
    // Like TildeExpand, but nullopt when the path starts with "~/" and HOME is not set.
    static std::optional<std::string> TildeExpandStrict(const std::string &path);

private:
    friend class IniParser;
    const IniSection *FindSection(const std::string &name) const;
    void Diagnose(const IniEntry &entry, const char *level, const std::string &what) const;
    bool NumberUsable(const IniEntry &entry, int conv, const char *kind) const;
    template <typename T>
    std::optional<T> FindMapped(const std::string &key, const std::string &section, int num,
                                std::optional<T> (*map)(const std::string &),
                                const char *invalid) const;

    std::vector<IniSection> sections_;
    std::string path_;
    std::string error_;
    bool open_ = false;
    bool quiet_ = false;
};

#endif
