// emc_nml_paths.cc: where the .nml file of a configuration is ([EMC]NML_FILE or the shipped default).
#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "emc_channel.hh"
#include "inifile.hh"

// Folder part of a path ("." when there is none).
static std::string dir_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

// Top of the tree (or prefix) this library was loaded from: <top>/lib/libemcnml.so.
static std::string library_top()
{
    Dl_info info;
    if (!dladdr(reinterpret_cast<void *>(&library_top), &info) || !info.dli_fname) return "";
    std::string lib_dir = dir_of(info.dli_fname);
    return dir_of(lib_dir);
}

// $EMC2_HOME/configs/common/linuxcnc.nml, else the one beside this library's tree.
std::string emc_default_nml_file()
{
    const char *home = getenv("EMC2_HOME");
    std::string top = home && *home ? home : library_top();
    std::string path = top + "/configs/common/linuxcnc.nml";
    if (access(path.c_str(), R_OK) == 0 || top.empty()) return path;
    std::string shared = top + "/share/openemc/linuxcnc.nml";
    return access(shared.c_str(), R_OK) == 0 ? shared : path;
}

// [EMC]NML_FILE of an INI file, relative to its folder; the default when absent.
std::string emc_nml_file_for_ini(const std::string &ini_path, std::string *error)
{
    IniFile ini;
    ini.SetQuiet(true);
    if (!ini.Open(ini_path)) {
        if (error) *error = ini_path + ": cannot read the INI file";
        return "";
    }
    std::optional<std::string> value = ini.Find("NML_FILE", "EMC");
    if (!value || value->empty()) return emc_default_nml_file();
    std::string file = IniFile::TildeExpand(*value);
    if (file[0] == '/') return file;
    return dir_of(ini_path) + "/" + file;
}
