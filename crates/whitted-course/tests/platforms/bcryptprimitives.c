/* bcryptprimitives.dll for Wine 8 (Debian 12), which lacks it: Rust's standard library for
 * Windows takes its random numbers from ProcessPrng there (Windows 10 and later, and Wine 9 and
 * later, have it). This one fills the buffer from RtlGenRandom (advapi32's SystemFunction036).
 * Built by crates/whitted-course/tests/platforms_build.rs with MinGW-w64 into Wine's system32. */
#include <windows.h>
BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);
__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        ULONG chunk = length > 0x40000000 ? 0x40000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
