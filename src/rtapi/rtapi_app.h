/* rtapi_app.h: entry points every realtime module defines (include in one file). */
#ifndef RTAPI_APP_H
#define RTAPI_APP_H

#include "rtapi.h"

RTAPI_BEGIN_DECLS

/* Called by rtapi_app after the module parameters are applied; <0 fails the load. */
extern RTAPI_VISIBLE int rtapi_app_main(void);
/* Called by rtapi_app before the module is unloaded. */
extern RTAPI_VISIBLE void rtapi_app_exit(void);

RTAPI_END_DECLS

#endif
