#pragma once
// The part of the survival shader's rewrite (survival.h) that leaves an application's fragment
// shader without effect on memory. Internal to layer/spirv/.
#include "layer/spirv/module.h"

namespace ds::layer {

// For the whole module (every entry point and function):
// - every Output variable becomes Private: the OpVariable and the OpTypePointer (and
//   OpTypeForwardPointer) of class Output; its interface decorations (Location, Component,
//   Index, BuiltIn, interpolation, Invariant...) go; below SPIR-V 1.4 it leaves every entry
//   point's interface (from 1.4 on it stays: the interface lists every global used);
// - execution modes DepthReplacing, DepthGreater, DepthLess, DepthUnchanged and
//   StencilRefReplacingEXT go;
// - every write through a pointer of a class other than Function, Private and Workgroup goes
//   (StorageBuffer, Uniform, PhysicalStorageBuffer, Image...): OpStore, OpCopyMemory(Sized),
//   OpAtomicStore, OpAtomicFlagClear; every OpImageWrite goes;
// - every atomic read-modify-write on such a pointer becomes an OpAtomicLoad of the same
//   result (type and id), pointer and scope, its semantics without Release, AcquireRelease
//   (made Acquire) and MakeAvailable; OpAtomicFlagTestAndSet becomes a load compared with 0.
// Discards (OpKill, OpTerminateInvocation, OpDemoteToHelperInvocation) stay.
void remove_memory_effects(Module& m);

}  // namespace ds::layer
