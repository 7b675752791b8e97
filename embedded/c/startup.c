/*
 * Start-up for the C firmware on a Cortex-M4F: the vector table, copying .data, clearing
 * .bss, enabling the FPU (the code is built for the hard-float ABI), semihosting for stdio
 * (newlib's rdimon), then main(); its return value is the exit status.
 */
#include <stdint.h>
#include <stdlib.h>

extern uint32_t _estack, _sidata, _sdata, _edata, _sbss, _ebss;
extern int main(void);
extern void initialise_monitor_handles(void);

void Reset_Handler(void) {
    for (uint32_t *src = &_sidata, *dst = &_sdata; dst < &_edata;) *dst++ = *src++;
    for (uint32_t *dst = &_sbss; dst < &_ebss;) *dst++ = 0;
    /* CPACR: full access to CP10 and CP11 (the FPU). */
    *(volatile uint32_t *)0xE000ED88 |= 0xFu << 20;
    __asm volatile("dsb\n isb");
    initialise_monitor_handles();
    exit(main());
}

/* A fault ends the run with a failure instead of hanging the emulator. */
void Fault_Handler(void) { abort(); }

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))&_estack, Reset_Handler, Fault_Handler, Fault_Handler,
    Fault_Handler,            Fault_Handler, Fault_Handler, 0, 0, 0, 0,
    Fault_Handler,            Fault_Handler, 0,             Fault_Handler, Fault_Handler,
};

/* newlib's init/fini arrays call these; nothing to do here. */
void _init(void) {}
void _fini(void) {}
