/*
 * What the C programs that compare themselves with the command share: a status check that
 * prints the last error, and a scene file read whole.
 */
#ifndef GDSMC_TESTS_SCENE_FILE_H
#define GDSMC_TESTS_SCENE_FILE_H

#include <stdio.h>
#include <stdlib.h>
#include "gdsmc.h"

static int check(gdsmc_status s, const char *what) {
    if (s != GDSMC_OK) {
        char msg[512];
        gdsmc_last_error(msg, sizeof msg);
        fprintf(stderr, "%s failed (status %d): %s\n", what, (int)s, msg);
        return 1;
    }
    return 0;
}

static char *read_file(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)len + 1);
    if (text && fread(text, 1, (size_t)len, f) != (size_t)len) {
        free(text);
        text = NULL;
    }
    if (text) text[len] = '\0';
    fclose(f);
    return text;
}

/* `*cfg` from the scene file at `path` (gdsmc_config_from_toml): 0, or 2 when the file cannot
 * be read, 1 when gdsmc refuses it (the message printed). */
static int config_of(const char *path, gdsmc_config *cfg) {
    char *text = read_file(path);
    if (!text) {
        fprintf(stderr, "cannot read %s\n", path);
        return 2;
    }
    gdsmc_status s = gdsmc_config_from_toml(text, cfg);
    free(text);
    return check(s, "gdsmc_config_from_toml");
}

#endif
