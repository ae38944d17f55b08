// sub_index.cc: finding "o<name> sub" lines without rescanning files: a per-file index, and subroutine
// files from the search path kept while they are unchanged on disk.
#include <sys/stat.h>

#include "interp.hh"

// The first "o<name> sub" of file at line `from` or later; the file is indexed on first use.
bool Interp::sub_in_file(const std::shared_ptr<SourceFile> &file, const std::string &name, size_t from,
                         SubDef &def)
{
    INTERP_FRAME();
    if (!file->subs_indexed) {
        std::string n;
        OKind k;
        for (size_t i = 0; i < file->lines.size(); i++)
            if (peek_oword(file->lines[i], n, k) && k == O_SUB) file->subs.emplace(n, i);
        file->subs_indexed = true;
    }
    auto range = file->subs.equal_range(name);
    for (auto it = range.first; it != range.second; ++it) {
        if (it->second < from) continue;
        def = SubDef{file, it->second};
        return true;
    }
    return false;
}

// A subroutine file of the search path, read again only when its modification time or size changed.
std::shared_ptr<SourceFile> Interp::load_sub_file(const std::string &path)
{
    INTERP_FRAME();
    struct stat st;
    if (stat(path.c_str(), &st) != 0) return nullptr;
    auto it = sub_files_.find(path);
    long long stamp = (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec + (long long)st.st_size;
    if (it != sub_files_.end() && it->second.first == stamp) return it->second.second;
    auto file = load_file(path);
    if (file) sub_files_[path] = {stamp, file};
    return file;
}
