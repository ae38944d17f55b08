/* mb_ini.h: a small INI reader that keeps the line of every entry, for mb2hal's error messages. */
#ifndef MB_INI_H
#define MB_INI_H

typedef struct {
    char *section;  /* section name without brackets */
    char *key;      /* key, whitespace trimmed */
    char *value;    /* value, whitespace trimmed */
    int line;       /* 1-based line in the file */
    int used;       /* set once a lookup returned it */
} mb_ini_entry_t;

typedef struct {
    const char *path;        /* file name used in messages */
    mb_ini_entry_t *entries; /* all KEY=VALUE lines in file order */
    int count;
    char **sections;         /* section names in file order */
    int *section_lines;
    int nsections;
} mb_ini_t;

/* Reads path into ini; returns 0, or -1 after printing "mb2hal: file:line: ..." on stderr. */
int mb_ini_load(mb_ini_t *ini, const char *path);
/* First entry for key in section, or NULL; marks it used. */
mb_ini_entry_t *mb_ini_get(mb_ini_t *ini, const char *section, const char *key);
/* Line of "[section]" or 0 when the section is absent. */
int mb_ini_section_line(const mb_ini_t *ini, const char *section);
/* Frees everything mb_ini_load allocated. */
void mb_ini_free(mb_ini_t *ini);

#endif
