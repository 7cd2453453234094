/* The process's peak and current resident memory (VmHWM, VmRSS from
 * /proc/self/status), as one line: "memory: VmHWM 110192 kB, VmRSS ...";
 * "?" where the kernel does not say. skinplay --report-memory, the soak. */
#ifndef MEM_REPORT_H
#define MEM_REPORT_H

#include <stdio.h>

void mem_report(FILE *to);

#endif
