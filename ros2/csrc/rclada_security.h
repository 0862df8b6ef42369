/*
 * Where Cyclone's DDS-Security plugins are (not for users: bound by
 * RCL.DDS). See rclada_security.c.
 */
#ifndef RCLADA_SECURITY_H
#define RCLADA_SECURITY_H

#include <stddef.h>

/* Writes into "dir" (of "size" bytes) the directory holding
   libdds_security_auth.so, libdds_security_ac.so and
   libdds_security_crypto.so: "libddsc0debian" beside the libddsc that is
   loaded (Debian's layout), else libddsc's own directory. Returns 0, or -1
   when neither holds the plugins or "dir" is too small. */
int rclada_security_plugin_dir (char *dir, size_t size);

#endif
