/* Cortex-M startup and semihosting for the embedded test under
 * qemu-system-arm (mps2-an386 for the M4, mps2-an385 for M0 code).
 *
 * Reset: copy .data from flash, clear .bss, enable the FPU when the build
 * uses it, run emb_main, report its status to the debugger (QEMU exits with
 * 0 for ADP_Stopped_ApplicationExit and 1 for any other reason). A fault
 * prints its name and exits with failure instead of hanging. */
#include <stdint.h>

#include "emb_port.h"

extern uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[];
extern uint32_t __stack_top[];

#define SYS_WRITE0 0x04
#define SYS_EXIT 0x18
#define ADP_STOPPED_APPLICATION_EXIT 0x20026
#define ADP_STOPPED_RUNTIME_ERROR 0x20023

static uint32_t semihost(uint32_t op, const void *arg)
{
	register uint32_t r0 __asm__("r0") = op;
	register const void *r1 __asm__("r1") = arg;
	__asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
	return r0;
}

void emb_puts(const char *s)
{
	semihost(SYS_WRITE0, s);
}

static void __attribute__((noreturn)) emb_exit(int status)
{
	semihost(SYS_EXIT, (const void *)(uintptr_t)(status ? ADP_STOPPED_RUNTIME_ERROR
							     : ADP_STOPPED_APPLICATION_EXIT));
	for (;;)
		;
}

void reset_handler(void);
void reset_handler(void)
{
	uint32_t *src = __data_load;
	for (uint32_t *d = __data_start; d < __data_end;)
		*d++ = *src++;
	for (uint32_t *d = __bss_start; d < __bss_end;)
		*d++ = 0;
#if defined(__ARM_FP)
	/* CPACR: full access to CP10 and CP11 before the first FPU instruction. */
	*(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
	__asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
	emb_exit(emb_main());
}

static void fault(const char *what)
{
	emb_puts("emb: ");
	emb_puts(what);
	emb_puts("\n");
	emb_exit(1);
}

static void nmi_handler(void) { fault("NMI"); }
static void hardfault_handler(void) { fault("HardFault"); }
static void other_handler(void) { fault("unexpected exception"); }

typedef void (*vector)(void);

__attribute__((section(".vectors"), used)) static const vector vectors[16] = {
	(vector)(uintptr_t)__stack_top,
	reset_handler,
	nmi_handler,
	hardfault_handler,
	other_handler, /* MemManage (M3/M4) */
	other_handler, /* BusFault */
	other_handler, /* UsageFault */
	0, 0, 0, 0,
	other_handler, /* SVCall */
	other_handler, /* DebugMon */
	0,
	other_handler, /* PendSV */
	other_handler, /* SysTick */
};
