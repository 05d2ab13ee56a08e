/* Preloaded into every process of the sanitizer stage (tests/sanitize/env.sh): dlclose keeps
 * the library loaded. LeakSanitizer checks at exit, after the Vulkan loader has dlclose'd the
 * driver and the layers; their allocations then point into unmapped code ("<unknown module>",
 * or worse, a neighbouring module's name), so no suppression can name them, and memory held by
 * an unloaded library's globals (libxml2, loaded by lavapipe's LLVM: 240 bytes) looks leaked.
 * Nothing in depthscope relies on a library really going away. */
int dlclose(void *handle) {
    (void)handle;
    return 0;
}
