// sub_files.cc: subroutine files of the search path, kept while they are unchanged on disk (a remap or
// call on every line of a program reads its file once, not once per call).
#include <sys/stat.h>

#include "interp.hh"

// A subroutine file of the search path, read again only when its modification time or size changed.
std::shared_ptr<SourceFile> Interp::load_sub_file(const std::string &path)
{
    INTERP_FRAME();
    struct stat st;
    if (stat(path.c_str(), &st) != 0) return nullptr;
    long long stamp = (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec + (long long)st.st_size;
    auto it = sub_files_.find(path);
    if (it != sub_files_.end() && it->second.first == stamp) return it->second.second;
    auto file = load_file(path);
    if (file) sub_files_[path] = {stamp, file};
    return file;
}
