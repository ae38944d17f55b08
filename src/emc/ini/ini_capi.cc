// ini_capi.cc: the C API of the INI library (LinuxCNC's path-based iniFind* and ini_open/ini_find handles).
#include "inifile.h"
#include "inifile.hh"

#include <cerrno>
#include <climits>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <sys/stat.h>
#include <tuple>

struct ini_file {
    IniFile ini;
};

namespace {

// Section argument of the C API: NULL means any section.
std::string section_arg(const char *section)
{
    return section ? section : "";
}

// Identity of a file's current content, used as cache key with its path.
using FileId = std::tuple<std::string, dev_t, ino_t, long, long, off_t>;

// Files parsed for the path-based API, kept for the life of the process (each parsed once per
// content, so their warnings are printed once).
std::map<FileId, std::unique_ptr<IniFile>> file_cache;
std::mutex file_cache_lock;

// Parse (or reuse) the INI file at path; nullptr when it cannot be loaded.
const IniFile *cached_file(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) st = {};
    FileId id{path, st.st_dev, st.st_ino, long(st.st_mtim.tv_sec), long(st.st_mtim.tv_nsec), st.st_size};
    std::lock_guard<std::mutex> guard(file_cache_lock);
    auto found = file_cache.find(id);
    if (found != file_cache.end()) return found->second->IsOpen() ? found->second.get() : nullptr;
    std::unique_ptr<IniFile> ini(new IniFile(path));
    const IniFile *result = ini->IsOpen() ? ini.get() : nullptr;
    if (result) file_cache[id] = std::move(ini);
    return result;
}

// The file behind a path-based lookup and the section to search; nullptr on bad arguments or
// a file that cannot be loaded.
const IniFile *lookup_file(const char *inipath, const char *tag, const void *result)
{
    if (!inipath || !tag || !result) return nullptr;
    return cached_file(inipath);
}

// Store a converted value or map the lookup outcome to -ENOENT / -EINVAL.
template <typename T, typename U>
int store(const IniFile &ini, const char *key, const char *section, int num,
          const std::optional<U> &value, T *out)
{
    if (value) {
        *out = T(*value);
        return 0;
    }
    return ini.FindEntry(key, section_arg(section), num) ? -EINVAL : -ENOENT;
}

} // namespace

// Open and parse.
ini_file_t *ini_open(const char *path)
{
    std::unique_ptr<ini_file> handle(new ini_file);
    if (!path || !handle->ini.Open(path)) return nullptr;
    return handle.release();
}

// Free a handle.
void ini_close(ini_file_t *ini)
{
    delete ini;
}

// num-th value of key.
const char *ini_find(const ini_file_t *ini, const char *key, const char *section, int num)
{
    if (!ini || !key) return nullptr;
    const IniEntry *entry = ini->ini.FindEntry(key, section_arg(section), num);
    return entry ? entry->value.c_str() : nullptr;
}

// Signed integer lookup.
int ini_find_int(const ini_file_t *ini, const char *key, const char *section, int num,
                 long long *value)
{
    if (!ini || !key || !value) return -EINVAL;
    return store(ini->ini, key, section, num, ini->ini.FindInt(key, section_arg(section), num), value);
}

// Unsigned integer lookup.
int ini_find_uint(const ini_file_t *ini, const char *key, const char *section, int num,
                  unsigned long long *value)
{
    if (!ini || !key || !value) return -EINVAL;
    return store(ini->ini, key, section, num, ini->ini.FindUInt(key, section_arg(section), num), value);
}

// Real lookup.
int ini_find_double(const ini_file_t *ini, const char *key, const char *section, int num,
                    double *value)
{
    if (!ini || !key || !value) return -EINVAL;
    return store(ini->ini, key, section, num, ini->ini.FindReal(key, section_arg(section), num), value);
}

// Boolean lookup (1/0).
int ini_find_bool(const ini_file_t *ini, const char *key, const char *section, int num, int *value)
{
    if (!ini || !key || !value) return -EINVAL;
    return store(ini->ini, key, section, num, ini->ini.FindBool(key, section_arg(section), num), value);
}

// Copy file with "~/" expanded into path.
int TildeExpansion(const char *file, char *path, size_t size)
{
    if (!file || !path || size == 0) return -EINVAL;
    std::optional<std::string> expanded = IniFile::TildeExpandStrict(file);
    if (!expanded) return -ENOENT;
    if (expanded->size() >= size) return -ENOSPC;
    memcpy(path, expanded->c_str(), expanded->size() + 1);
    return 0;
}

// First value of tag, copied into buf.
int iniFindString(const char *inipath, const char *tag, const char *section, char *buf, size_t bufsize)
{
    const IniFile *ini = lookup_file(inipath, tag, buf);
    if (!ini || bufsize == 0) return -EINVAL;
    const IniEntry *entry = ini->FindEntry(tag, section_arg(section), 1);
    if (!entry) return -ENOENT;
    if (entry->value.size() >= bufsize) return -ENOSPC;
    memcpy(buf, entry->value.c_str(), entry->value.size() + 1);
    return 0;
}

// Store a typed lookup's value: 0, or -ENOENT when missing or not convertible.
template <typename T, typename U>
int store_first(const std::optional<U> &value, T *result)
{
    if (!value) return -ENOENT;
    *result = T(*value);
    return 0;
}

// First value of tag as a boolean.
int iniFindBool(const char *inipath, const char *tag, const char *section, bool *result)
{
    const IniFile *ini = lookup_file(inipath, tag, result);
    if (!ini) return -EINVAL;
    return store_first(ini->FindBool(tag, section_arg(section), 1), result);
}

// First value of tag as a signed 64-bit integer.
int iniFindSInt(const char *inipath, const char *tag, const char *section, rtapi_s64 *result)
{
    const IniFile *ini = lookup_file(inipath, tag, result);
    if (!ini) return -EINVAL;
    return store_first(ini->FindInt(tag, section_arg(section), 1), result);
}

// First value of tag as an unsigned 64-bit integer.
int iniFindUInt(const char *inipath, const char *tag, const char *section, rtapi_u64 *result)
{
    const IniFile *ini = lookup_file(inipath, tag, result);
    if (!ini) return -EINVAL;
    return store_first(ini->FindUInt(tag, section_arg(section), 1), result);
}

// First value of tag as a real.
int iniFindDouble(const char *inipath, const char *tag, const char *section, double *result)
{
    const IniFile *ini = lookup_file(inipath, tag, result);
    if (!ini) return -EINVAL;
    return store_first(ini->FindReal(tag, section_arg(section), 1), result);
}

// iniFindSInt truncated to int.
int iniFindInt(const char *inipath, const char *tag, const char *section, int *result)
{
    rtapi_s64 value = 0;
    int rc = result ? iniFindSInt(inipath, tag, section, &value) : -EINVAL;
    if (rc == 0) *result = int(value);
    return rc;
}
