/* vk_int.h - what vk_run.c needs of vk.c's device (not for the study). */
#ifndef ONB_GPU_VK_INT_H
#define ONB_GPU_VK_INT_H
#include <vulkan/vulkan.h>
#include "gpu/vk.h"
VkDevice gpu__dev(const gpu_dev *d);
VkQueue gpu__queue(const gpu_dev *d);
uint32_t gpu__qfam(const gpu_dev *d);
const VkPhysicalDeviceMemoryProperties *gpu__mem(const gpu_dev *d);
#endif
