/*
 * Where Cyclone's DDS-Security plugins are: found from the path of the
 * libddsc actually loaded (dladdr), so that the plugins always match it.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "dds/dds.h"
#include "rclada_security.h"

static int holds_plugins (const char *dir)
{
  char path[4096];
  if (snprintf (path, sizeof (path), "%s/libdds_security_auth.so", dir) >= (int) sizeof (path))
    return 0;
  return access (path, R_OK) == 0;
}

int rclada_security_plugin_dir (char *dir, size_t size)
{
  Dl_info info;
  char own[4096];
  const char *slash;
  size_t len;

  if (dladdr ((void *) dds_create_participant, &info) == 0 || info.dli_fname == NULL)
    return -1;
  slash = strrchr (info.dli_fname, '/');
  if (slash == NULL)
    return -1;
  len = (size_t) (slash - info.dli_fname);
  if (len + 1 > sizeof (own))
    return -1;
  memcpy (own, info.dli_fname, len);
  own[len] = '\0';
  if (snprintf (dir, size, "%s/libddsc0debian", own) < (int) size && holds_plugins (dir))
    return 0;
  if (snprintf (dir, size, "%s", own) < (int) size && holds_plugins (dir))
    return 0;
  return -1;
}
