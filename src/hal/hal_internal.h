/* hal_internal.h: declarations shared by the HAL library's own source files only. */
#ifndef HAL_INTERNAL_H
#define HAL_INTERNAL_H

#include "hal_priv.h"
#include "rtapi_instance.h"
#include <errno.h>
#include <string.h>

/* per-process library state */
extern int hal_proc_is_rt;       /* this process is rtapi_app (hal_lib loaded) */
extern int hal_proc_lib_id;      /* rtapi id of the library attach, 0 = none */
extern int hal_proc_comps;       /* components created by this process */

#define HAL_ERR(...) rtapi_print_msg(RTAPI_MSG_ERR, "HAL: ERROR: " __VA_ARGS__)
#define HAL_LIB_ERR(...) rtapi_print_msg(RTAPI_MSG_ERR, "HAL_LIB: ERROR: " __VA_ARGS__)

/* hal_lock.c */
int halpr_check_unlocked(const char *what, unsigned lock_bits, const char *locked_fmt);

/* hal_memory.c */
int hal_shm_attach(void);
void hal_shm_detach(void);
void *halpr_obj_alloc(int kind);
void halpr_obj_free(int kind, void *obj);
void *halpr_malloc(long size);
int hal_lib_attach(void);
int hal_attach_user(void);

/* hal_index.c */
hal_node_t *halpr_index_find(hal_index_t *ix, const char *name);
void halpr_index_insert_sorted(hal_index_t *ix, hal_node_t *n);
void halpr_index_insert_head(hal_index_t *ix, hal_node_t *n);
void halpr_index_remove(hal_index_t *ix, hal_node_t *n);
int halpr_index_setup(hal_index_t *ix, int nbuckets);
int halpr_name_check(const char *kind, const char *name, size_t max_len);

/* hal_comp.c */
void halpr_comp_free_items(hal_comp_t *comp);
unsigned long long halpr_process_start(int pid);
int halpr_comp_owner_alive(const hal_comp_t *comp);
int halpr_comp_check(int comp_id, const char *what, hal_comp_t **out);

/* hal_pin.c / hal_param.c */
int halpr_pin_create(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id);
void halpr_pin_free(hal_pin_t *pin);
void halpr_param_free(hal_param_t *param);
int halpr_name_fmt(char *buf, const char *fmt, va_list ap);

/* hal_item_new.c (is_pin selects pin or param; dir is the pin or param direction) */
int halpr_item_new_va(int is_pin, hal_type_t type, int dir, void *addr, int comp_id,
                      const char *fmt, va_list ap);
int halpr_item_new_ref(int is_pin, hal_type_t type, int dir, void **ref, int comp_id,
                       const char *fmt, va_list ap);

/* hal_signal.c */
void halpr_unlink_pin(hal_pin_t *pin);
void halpr_sig_pin_insert(hal_sig_t *sig, hal_pin_t *pin);
void halpr_sig_pin_remove(hal_sig_t *sig, hal_pin_t *pin);

/* hal_funct.c / hal_thread_funct.c */
void halpr_funct_free(hal_funct_t *funct);
void halpr_thread_drop_funct(hal_funct_t *funct);
void halpr_entry_list_free(int *list);

/* hal_thread.c */
void halpr_thread_park(hal_comp_t *comp);
void halpr_thread_creator_exit(hal_comp_t *comp);
int halpr_thread_delete(hal_thread_t *thread);

/* hal_thread_run.c */
void hal_thread_task(void *arg);
void hal_clock_calibrate(void);


#endif
