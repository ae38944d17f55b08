// ini_lookup.cc: IniFile lookups: N-th value of a key, typed reads with diagnostics, sections and enums.
#include "inifile.hh"
#include "ini_text.hh"

#include <cmath>
#include <cstdio>
#include <cstdlib>

// Section by name, or nullptr.
const IniSection *IniFile::FindSection(const std::string &name) const
{
    for (const IniSection &sec : sections_)
        if (sec.name == name) return &sec;
    return nullptr;
}

// The num-th entry of key in section ("" = every section in file order).
const IniEntry *IniFile::FindEntry(const std::string &key, const std::string &section,
                                   int num) const
{
    if (num < 1) return nullptr;
    for (const IniSection &sec : sections_) {
        if (!section.empty() && sec.name != section) continue;
        for (const IniEntry &entry : sec.entries)
            if (entry.key == key && --num == 0) return &entry;
    }
    return nullptr;
}

// The num-th value of key.
std::optional<std::string> IniFile::Find(const std::string &key, const std::string &section,
                                         int num) const
{
    const IniEntry *entry = FindEntry(key, section, num);
    if (!entry) return std::nullopt;
    return entry->value;
}

// Print "<file>:<line>: <level>: <what>" unless quiet.
void IniFile::Diagnose(const IniEntry &entry, const char *level, const std::string &what) const
{
    if (quiet_) return;
    fprintf(stderr, "%s:%d: %s: %s\n", entry.file.c_str(), entry.line, level, what.c_str());
}

// "[S]K='value'" of an entry, as diagnostics quote it.
static std::string quoted(const IniEntry &entry)
{
    return "[" + entry.section + "]" + entry.key + "='" + entry.value + "'";
}

// Report the outcome of a number conversion; true when the number may be used.
bool IniFile::NumberUsable(const IniEntry &entry, int conv, const char *kind) const
{
    IniConv c = IniConv(conv);
    if (c == IniConv::trailing)
        Diagnose(entry, "warning", std::string("Trailing character(s) in ") + kind + " conversion (" +
                                       quoted(entry) + ")");
    if (c == IniConv::invalid) Diagnose(entry, "error", std::string("Invalid ") + kind + " " + quoted(entry));
    return c != IniConv::invalid;
}

// Signed integer value.
std::optional<long long> IniFile::FindInt(const std::string &key, const std::string &section,
                                          int num) const
{
    const IniEntry *entry = FindEntry(key, section, num);
    long long value = 0;
    if (!entry) return std::nullopt;
    IniConv conv = ini_parse_int(ini_trim(entry->value), value);
    if (!NumberUsable(*entry, int(conv), "signed integer")) return std::nullopt;
    return value;
}

// Unsigned integer value (a negative value wraps, after a warning).
std::optional<unsigned long long> IniFile::FindUInt(const std::string &key,
                                                    const std::string &section, int num) const
{
    const IniEntry *entry = FindEntry(key, section, num);
    unsigned long long value = 0;
    if (!entry) return std::nullopt;
    std::string text = ini_trim(entry->value);
    if (!text.empty() && text[0] == '-')
        Diagnose(*entry, "warning", "Unsigned integer conversion detected a leading minus sign (-)");
    IniConv conv = ini_parse_uint(text, value);
    if (!NumberUsable(*entry, int(conv), "unsigned integer")) return std::nullopt;
    return value;
}

// Real value.
std::optional<double> IniFile::FindReal(const std::string &key, const std::string &section,
                                        int num) const
{
    const IniEntry *entry = FindEntry(key, section, num);
    double value = 0;
    if (!entry) return std::nullopt;
    IniConv conv = ini_parse_real(ini_trim(entry->value), value);
    if (!NumberUsable(*entry, int(conv), "floating point")) return std::nullopt;
    return value;
}

// Strict boolean value.
std::optional<bool> IniFile::FindBool(const std::string &key, const std::string &section,
                                      int num) const
{
    const IniEntry *entry = FindEntry(key, section, num);
    bool value = false;
    if (!entry) return std::nullopt;
    if (!ini_parse_bool(ini_trim(entry->value), value)) {
        Diagnose(*entry, "error", "Invalid boolean value " + quoted(*entry));
        return std::nullopt;
    }
    return value;
}

// An enum value of key through map; diagnoses `invalid` when map knows no such word.
template <typename T>
std::optional<T> IniFile::FindMapped(const std::string &key, const std::string &section, int num,
                                     std::optional<T> (*map)(const std::string &),
                                     const char *invalid) const
{
    const IniEntry *entry = FindEntry(key, section, num);
    if (!entry) return std::nullopt;
    std::optional<T> value = map(ini_trim(entry->value));
    if (!value) Diagnose(*entry, "error", std::string(invalid) + " " + quoted(*entry));
    return value;
}

// LINEAR_UNITS value as units per mm.
std::optional<double> IniFile::FindLinearUnits(const std::string &key,
                                               const std::string &section, int num) const
{
    return FindMapped(key, section, num, MapLinearUnits, "Invalid linear units");
}

// ANGULAR_UNITS value as units per degree.
std::optional<double> IniFile::FindAngularUnits(const std::string &key,
                                                const std::string &section, int num) const
{
    return FindMapped(key, section, num, MapAngularUnits, "Invalid angular units");
}

// Joint TYPE value (1 linear, 2 angular).
std::optional<int> IniFile::FindJointType(const std::string &key, const std::string &section,
                                          int num) const
{
    return FindMapped(key, section, num, MapJointType, "Invalid joint type");
}

// mm|metric -> 1, in|inch|imperial -> 1/25.4.
std::optional<double> IniFile::MapLinearUnits(const std::string &text)
{
    if (ini_iequal(text, "mm") || ini_iequal(text, "metric")) return 1.0;
    if (ini_iequal(text, "in") || ini_iequal(text, "inch") || ini_iequal(text, "imperial"))
        return 1.0 / 25.4;
    return std::nullopt;
}

// deg|degree -> 1, rad|radian -> pi/180, grad|gon -> 0.9.
std::optional<double> IniFile::MapAngularUnits(const std::string &text)
{
    if (ini_iequal(text, "deg") || ini_iequal(text, "degree")) return 1.0;
    if (ini_iequal(text, "rad") || ini_iequal(text, "radian")) return M_PI / 180.0;
    if (ini_iequal(text, "grad") || ini_iequal(text, "gon")) return 0.9;
    return std::nullopt;
}

// LINEAR -> 1, ANGULAR -> 2.
std::optional<int> IniFile::MapJointType(const std::string &text)
{
    if (ini_iequal(text, "LINEAR")) return 1;
    if (ini_iequal(text, "ANGULAR")) return 2;
    return std::nullopt;
}

// Every value of key, in file order.
std::vector<std::string> IniFile::FindAll(const std::string &key, const std::string &section) const
{
    std::vector<std::string> values;
    for (const IniSection &sec : sections_) {
        if (!section.empty() && sec.name != section) continue;
        for (const IniEntry &entry : sec.entries)
            if (entry.key == key) values.push_back(entry.value);
    }
    return values;
}

// Does the section exist?
bool IniFile::HasSection(const std::string &section) const
{
    return FindSection(section) != nullptr;
}

// Section names in file order.
std::vector<std::string> IniFile::Sections() const
{
    std::vector<std::string> names;
    for (const IniSection &sec : sections_) names.push_back(sec.name);
    return names;
}

// (key, value) pairs of one section or of all sections.
std::vector<std::pair<std::string, std::string>> IniFile::Variables(const std::string &section) const
{
    std::vector<std::pair<std::string, std::string>> vars;
    for (const IniSection &sec : sections_) {
        if (!section.empty() && sec.name != section) continue;
        for (const IniEntry &entry : sec.entries) vars.emplace_back(entry.key, entry.value);
    }
    return vars;
}

// Leading "~/" -> "$HOME/".
std::string IniFile::TildeExpand(const std::string &path)
{
    return TildeExpandStrict(path).value_or(path);
}

// Leading "~/" -> "$HOME/"; nullopt when HOME is needed but not set.
std::optional<std::string> IniFile::TildeExpandStrict(const std::string &path)
{
    if (path.compare(0, 2, "~/") != 0) return path;
    const char *home = getenv("HOME");
    if (!home) return std::nullopt;
    return std::string(home) + path.substr(1);
}
