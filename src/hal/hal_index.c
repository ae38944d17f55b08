/* hal_index.c: name indexes: hash lookup plus doubly linked listing order (sorted or newest first). */
#include "hal_internal.h"

/* FNV-1a hash of a name. */
static unsigned hal_name_hash(const char *name)
{
    unsigned h = 2166136261u;
    while (*name)
        h = (h ^ (unsigned char)*name++) * 16777619u;
    return h;
}

/* Check a new object's name: not empty, at most max_len bytes, no white space or control
   characters (they could never be named in a HAL file), not ending in '.' (an empty last
   part, as a prefix with an empty pin name gives); 0 or -EINVAL after a message. */
int halpr_name_check(const char *kind, const char *name, size_t max_len)
{
    if (!name || !*name) {
        HAL_ERR("%s name is empty\n", kind);
        return -EINVAL;
    }
    if (strlen(name) > max_len) {
        HAL_ERR("%s name '%s' is too long\n", kind, name);
        return -EINVAL;
    }
    for (const char *p = name; *p; p++) {
        if ((unsigned char)*p <= ' ' || *p == 0x7f) {
            HAL_ERR("%s name '%s' contains white space or control characters\n", kind, name);
            return -EINVAL;
        }
    }
    if (name[strlen(name) - 1] == '.') {
        HAL_ERR("%s name '%s' ends with '.'\n", kind, name);
        return -EINVAL;
    }
    return 0;
}

/* Hash bucket head for a name. */
static int *hal_bucket(hal_index_t *ix, const char *name)
{
    int *heads = SHMPTR(ix->hash_ptr);
    return &heads[hal_name_hash(name) & (ix->nbuckets - 1)];
}

/* Allocate the bucket array of an index (creator only). */
int halpr_index_setup(hal_index_t *ix, int nbuckets)
{
    int *heads = halpr_malloc((long)nbuckets * sizeof(int));
    if (!heads)
        return -ENOMEM;
    ix->hash_ptr = SHMOFF(heads);
    ix->nbuckets = nbuckets;
    return 0;
}

/* Object with exactly this current name, or NULL. */
hal_node_t *halpr_index_find(hal_index_t *ix, const char *name)
{
    int off;

    if (!name)
        return NULL;
    off = *hal_bucket(ix, name);
    while (off) {
        hal_node_t *n = SHMPTR(off);
        if (strcmp(n->name, name) == 0)
            return n;
        off = n->hash_next;
    }
    return NULL;
}

/* Add n to the hash chain of its name. */
static void hal_hash_add(hal_index_t *ix, hal_node_t *n)
{
    int *head = hal_bucket(ix, n->name);
    n->hash_next = *head;
    *head = SHMOFF(n);
}

/* Link n into the list right after prev (prev NULL = at the head). */
static void hal_list_link_after(hal_index_t *ix, hal_node_t *prev, hal_node_t *n)
{
    int next = prev ? prev->next_ptr : ix->list_ptr;
    n->prev_ptr = prev ? SHMOFF(prev) : 0;
    n->next_ptr = next;
    if (next)
        ((hal_node_t *)SHMPTR(next))->prev_ptr = SHMOFF(n);
    if (prev)
        prev->next_ptr = SHMOFF(n);
    else
        ix->list_ptr = SHMOFF(n);
}

/* Insert n in strcmp order, searching from the last insert point (finger). */
void halpr_index_insert_sorted(hal_index_t *ix, hal_node_t *n)
{
    hal_node_t *prev = ix->hint_ptr ? SHMPTR(ix->hint_ptr) : NULL;

    if (prev && strcmp(prev->name, n->name) < 0) {
        while (prev->next_ptr) {
            hal_node_t *next = SHMPTR(prev->next_ptr);
            if (strcmp(next->name, n->name) >= 0)
                break;
            prev = next;
        }
    } else {
        while (prev && strcmp(prev->name, n->name) >= 0)
            prev = prev->prev_ptr ? SHMPTR(prev->prev_ptr) : NULL;
    }
    hal_list_link_after(ix, prev, n);
    hal_hash_add(ix, n);
    ix->hint_ptr = SHMOFF(n);
}

/* Insert n at the head of the list (newest first). */
void halpr_index_insert_head(hal_index_t *ix, hal_node_t *n)
{
    hal_list_link_after(ix, NULL, n);
    hal_hash_add(ix, n);
}

/* Remove n from the list and its hash chain. */
void halpr_index_remove(hal_index_t *ix, hal_node_t *n)
{
    int *link = hal_bucket(ix, n->name);
    int off = SHMOFF(n);

    while (*link && *link != off)
        link = &((hal_node_t *)SHMPTR(*link))->hash_next;
    if (*link)
        *link = n->hash_next;
    if (n->prev_ptr)
        ((hal_node_t *)SHMPTR(n->prev_ptr))->next_ptr = n->next_ptr;
    else
        ix->list_ptr = n->next_ptr;
    if (n->next_ptr)
        ((hal_node_t *)SHMPTR(n->next_ptr))->prev_ptr = n->prev_ptr;
    if (ix->hint_ptr == off)
        ix->hint_ptr = n->prev_ptr ? n->prev_ptr : n->next_ptr;
    n->next_ptr = n->prev_ptr = n->hash_next = 0;
}
