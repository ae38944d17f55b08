/* canopen_sdo.c: build expedited SDO download requests and judge the drive's answers. */
#include "canopen_sdo.h"

/* The download request for w to node. */
void co_sdo_download_frame(uint8_t node, const co_sdo_write_t *w, co_frame_t *f)
{
    f->id = (uint16_t)(CO_SDO_RX + node);
    f->len = 8;
    f->rtr = 0;
    f->data[0] = (uint8_t)(CO_SDO_CCS_DOWNLOAD | CO_SDO_EXPEDITED | CO_SDO_SIZE_SET | ((4 - w->size) << 2));
    co_put16(&f->data[1], w->index);
    f->data[3] = w->sub;
    co_put32(&f->data[4], w->value);
}

/* Judge a frame received on the node's SDO response COB-ID. */
co_sdo_reply_t co_sdo_download_reply(const co_frame_t *f, const co_sdo_write_t *w, uint32_t *abort_code)
{
    if (f->rtr || f->len != 8)
        return CO_SDO_REPLY_MALFORMED;
    if (co_get16(&f->data[1]) != w->index || f->data[3] != w->sub)
        return CO_SDO_REPLY_UNRELATED;
    if (f->data[0] == CO_SDO_ABORT) {
        *abort_code = co_get32(&f->data[4]);
        return CO_SDO_REPLY_ABORT;
    }
    if (f->data[0] == CO_SDO_SCS_DOWNLOAD)
        return CO_SDO_REPLY_DONE;
    return CO_SDO_REPLY_MALFORMED;
}

/* Abort codes of CiA 301 with a short description each. */
static const struct {
    uint32_t code;
    const char *text;
} abort_texts[] = {
    { CO_ABORT_TIMEOUT, "SDO protocol timed out" },
    { CO_ABORT_COMMAND, "command specifier not valid or unknown" },
    { CO_ABORT_UNSUPPORTED_ACCESS, "unsupported access to an object" },
    { CO_ABORT_WRITE_ONLY, "attempt to read a write-only object" },
    { CO_ABORT_READ_ONLY, "attempt to write a read-only object" },
    { CO_ABORT_NO_OBJECT, "object does not exist in the object dictionary" },
    { CO_ABORT_NOT_MAPPABLE, "object cannot be mapped to the PDO" },
    { CO_ABORT_PDO_TOO_LONG, "the mapped objects would exceed the PDO length" },
    { 0x06040043u, "general parameter incompatibility" },
    { 0x06040047u, "general internal incompatibility in the device" },
    { 0x06060000u, "access failed due to a hardware error" },
    { CO_ABORT_LENGTH, "data type does not match, length of service parameter does not match" },
    { 0x06070012u, "data type does not match, length of service parameter too high" },
    { 0x06070013u, "data type does not match, length of service parameter too low" },
    { CO_ABORT_NO_SUBINDEX, "sub-index does not exist" },
    { 0x06090030u, "value range of parameter exceeded" },
    { 0x06090031u, "value of parameter written too high" },
    { 0x06090032u, "value of parameter written too low" },
    { 0x06090036u, "maximum value is less than minimum value" },
    { CO_ABORT_GENERAL, "general error" },
    { 0x08000020u, "data cannot be transferred or stored to the application" },
    { 0x08000021u, "data cannot be transferred because of local control" },
    { CO_ABORT_DEVICE_STATE, "data cannot be transferred because of the present device state" },
};

/* A short description of an SDO abort code. */
const char *co_abort_text(uint32_t code)
{
    for (unsigned i = 0; i < sizeof(abort_texts) / sizeof(abort_texts[0]); i++)
        if (abort_texts[i].code == code)
            return abort_texts[i].text;
    return "unknown abort code";
}
