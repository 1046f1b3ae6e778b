/*
 * vk.h - the smallest Vulkan compute harness the shader study needs: one
 * device (lavapipe by default), one storage buffer in and one out, one
 * SPIR-V module whose specialization constant 0 picks the kernel, and a
 * dispatch of one invocation per element.  Part of onbstudy-gpu (make
 * gpu), never of libonb.a or ./onbstudy: it links libvulkan.
 *
 * Every call returns 0, or -1 after a message on stderr that names the
 * Vulkan call and its VkResult; nothing here exits.
 */
#ifndef ONB_GPU_VK_H
#define ONB_GPU_VK_H

#include <stddef.h>
#include <stdint.h>

typedef struct gpu_dev gpu_dev;

/* The first physical device whose name contains `want` ("llvmpipe" is
   lavapipe; "" takes the first device).  NULL, after a message that lists
   the devices seen, when there is none or it cannot be created. */
gpu_dev *gpu_open(const char *want);
void gpu_close(gpu_dev *d);

/* The device's name, driver name and driver info (Mesa's version string),
   Vulkan API version, and whether shaderFloat64 is enabled. */
const char *gpu_name(const gpu_dev *d);
const char *gpu_driver(const gpu_dev *d);
uint32_t gpu_api(const gpu_dev *d);
int gpu_float64(const gpu_dev *d);
/* Whether shaderFloat16 (explicit binary16 arithmetic) is enabled. */
int gpu_float16(const gpu_dev *d);
/* The float controls the driver reports (VkPhysicalDeviceFloatControlsProperties),
   one line of text, float32 then float16: denormals preserved or flushed,
   signed zeros kept, RTE. */
const char *gpu_float_controls(const gpu_dev *d);

/* Run the SPIR-V file `spv` (entry point "main", local size 64) with
   specialization constant 0 = `kernel`: binding 0 holds `in_words` 32-bit
   words from `in`, binding 1 receives `out_words` words into `out`;
   `groups` workgroups are dispatched. */
int gpu_run(gpu_dev *d, const char *spv, int32_t kernel,
            const uint32_t *in, size_t in_words, uint32_t *out, size_t out_words,
            uint32_t groups);

#endif
