/*
 * xfgcu_config.h - xfgcu's options for this firmware (named by
 * -DXF_CONFIG_HEADER="xfgcu_config.h", read before every default).
 * A host only receives GCU replies (72 or 73 bytes) and sends packets of at
 * most 84: the smallest buffers that hold them, and a small command queue.
 */
#ifndef XFGCU_CONFIG_H
#define XFGCU_CONFIG_H

#define XF_PACKET_MAX_LEN 84 /* the longest packet of the protocol (gaze_geo) */
#define XF_PARSER_SLOTS   4  /* the default: 4 B of RAM; a frame is lost only to 4 false candidates ending after it */
#define XF_CLIENT_QUEUE   2  /* commands waiting: this firmware sends one at a time */
#define XF_CLIENT_RESULTS 2  /* finished commands kept for polling */

#endif
