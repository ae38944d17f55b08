/* inc_value.h: constant used by the include test component. */
#define INC_VALUE 40
