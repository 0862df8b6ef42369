/*
 * Liveliness of the writers a reader matches (not for users: bound by
 * RCL.DDS). Cyclone reports liveliness changes to a listener, one call per
 * change, in its own thread; the tracker queues them (writer GUID, alive or
 * not) for the owner to take when it polls. See rclada_liveliness.c.
 */
#ifndef RCLADA_LIVELINESS_H
#define RCLADA_LIVELINESS_H

#include "dds/dds.h"

struct rclada_liveliness_tracker;

/* Installs a liveliness-changed listener on "reader" (replacing its
   listener, if any) and queues an "alive" change for every writer the
   reader matches already (changes from before the call are not reported
   otherwise). NULL when out of memory or on a DDS error. */
struct rclada_liveliness_tracker *rclada_liveliness_attach (dds_entity_t reader);

/* Takes the oldest queued change: 1 taken (guid and alive written; alive 1
   when the writer became alive, 0 when it lost its liveliness or was
   deleted), 0 none queued. */
int rclada_liveliness_take (struct rclada_liveliness_tracker *tracker,
                            unsigned char guid[16], int *alive);

/* Number of changes dropped because the queue was full (its capacity is
   fixed): the owner then knows its view may be stale. */
unsigned rclada_liveliness_dropped (struct rclada_liveliness_tracker *tracker);

/* Removes the listener from "reader" (if it still exists) and frees the
   tracker. */
void rclada_liveliness_detach (dds_entity_t reader, struct rclada_liveliness_tracker *tracker);

#endif
