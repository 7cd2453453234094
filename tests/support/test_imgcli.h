/* What test_image_cli and test_image_cli_damage share: reading the files
 * the tools write, skintool info's verdict on an image, and the shared
 * CMU walk. */
#ifndef TEST_IMGCLI_H
#define TEST_IMGCLI_H

/* The whole file at path, for the caller to free (the test fails when it
 * cannot be read). */
char *imgcli_slurp(const char *path);

/* Runs skintool info; returns its status and checks that the only blocks
 * it names bad are want (-1: none). */
int imgcli_info_names(const char *image, long want);

/* The shared CMU walk (02.asf, 02_01.amc) into asf and amc (1024 bytes
 * each); 0 when the shared data is not there. */
int imgcli_cmu_walk(char *asf, char *amc);

#endif
