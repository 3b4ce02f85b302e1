// Compiled into every executable of the sanitizer build (CMakeLists.txt,
// MPR_SANITIZE). intercept_tls_get_addr=0: up to LLVM 16, AddressSanitizer's
// __tls_get_addr interceptor takes a dynamic TLS block whose address happens
// to lie at a glibc 2.19 header's offset within its page for such a header
// (there is none since glibc 2.25) and reads a bogus range from before it;
// LeakSanitizer's tracer then dies scanning it ("Tracer caught signal 11"),
// a flake in any process that dlopens a library with thread-locals (the
// image module's OpenImageIO, OSMesa). Without the interceptor those blocks
// are not scanned for pointers; nothing of MPR's lives in them.
extern "C" const char* __asan_default_options() { return "intercept_tls_get_addr=0"; }
