// ini_capi.cc: the C API of the INI library (ini_open/ini_find handles and LinuxCNC-style iniFind on FILE*).
#include "inifile.h"
#include "inifile.hh"

#include <cerrno>
#include <climits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <sys/stat.h>
#include <tuple>
#include <unistd.h>

struct ini_file {
    IniFile ini;
};

namespace {

// Section argument of the C API: NULL means any section.
std::string section_arg(const char *section)
{
    return section ? section : "";
}

// Identity of an open file's current content, used as cache key.
using FileId = std::tuple<dev_t, ino_t, long, long, off_t>;

// Parsed files behind iniFind, kept for the life of the process so returned pointers stay valid.
std::map<FileId, std::unique_ptr<IniFile>> file_cache;
std::mutex file_cache_lock;

// Parse (or reuse) the INI file open as fp; nullptr when it cannot be loaded.
const IniFile *cached_file(FILE *fp)
{
    struct stat st;
    if (!fp || fstat(fileno(fp), &st) != 0) return nullptr;
    FileId id{st.st_dev, st.st_ino, long(st.st_mtim.tv_sec), long(st.st_mtim.tv_nsec), st.st_size};
    std::lock_guard<std::mutex> guard(file_cache_lock);
    auto found = file_cache.find(id);
    if (found != file_cache.end()) return found->second->IsOpen() ? found->second.get() : nullptr;
    char link[64], path[PATH_MAX];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fileno(fp));
    ssize_t n = readlink(link, path, sizeof path - 1);
    if (n <= 0) return nullptr;
    path[n] = '\0';
    std::unique_ptr<IniFile> ini(new IniFile(path));
    const IniFile *result = ini->IsOpen() ? ini.get() : nullptr;
    file_cache[id] = std::move(ini);
    return result;
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

// LinuxCNC-style first value of tag in section.
const char *iniFind(FILE *fp, const char *tag, const char *section)
{
    const IniFile *ini = cached_file(fp);
    if (!ini || !tag) return nullptr;
    const IniEntry *entry = ini->FindEntry(tag, section_arg(section), 1);
    return entry ? entry->value.c_str() : nullptr;
}

// LinuxCNC-style int lookup: 0 ok, -1 missing/invalid/out of int range.
int iniFindInt(FILE *fp, const char *tag, const char *section, int *result)
{
    const IniFile *ini = cached_file(fp);
    if (!ini || !tag || !result) return -1;
    std::optional<long long> value = ini->FindInt(tag, section_arg(section), 1);
    if (!value || *value < INT_MIN || *value > INT_MAX) return -1;
    *result = int(*value);
    return 0;
}

// LinuxCNC-style double lookup: 0 ok, -1 missing/invalid.
int iniFindDouble(FILE *fp, const char *tag, const char *section, double *result)
{
    const IniFile *ini = cached_file(fp);
    if (!ini || !tag || !result) return -1;
    std::optional<double> value = ini->FindReal(tag, section_arg(section), 1);
    if (!value) return -1;
    *result = *value;
    return 0;
}
