component classicladder_rt "ClassicLadder soft PLC: realtime ladder scan driven by HAL pins";
modparam dummy numRungs "Number of rungs, 1 to 10000 (default 100).";
modparam dummy numBits "Memory bits %B, 0 to 100000 (default 20).";
modparam dummy numWords "Memory words %W (signed 32 bit), 0 to 100000 (default 20).";
modparam dummy numTimers "Classic timers %T, 0 to 10000 (default 10).";
modparam dummy numMonostables "Monostables %M, 0 to 10000 (default 10).";
modparam dummy numCounters "Counters %C, 0 to 10000 (default 10).";
modparam dummy numPhysInputs "Bit input pins in-NN (%I), 0 to 1000 (default 15).";
modparam dummy numPhysOutputs "Bit output pins out-NN (%Q), 0 to 1000 (default 15).";
modparam dummy numArithmExpr "Arithmetic expressions for compare and operate elements, 0 to 10000 (default 50).";
modparam dummy numSections "Sections (main programs and subroutines), 1 to 1000 (default 10).";
modparam dummy numSymbols "Symbols, 0 to 100000 (default 100).";
modparam dummy numS32in "s32 input pins s32in-NN (%IW), 0 to 1000 (default 10).";
modparam dummy numS32out "s32 output pins s32out-NN (%QW), 0 to 1000 (default 10).";
modparam dummy numFloatIn "Float input pins floatin-NN (%IF), 0 to 1000 (default 10).";
modparam dummy numFloatOut "Float output pins floatout-NN (%QF), 0 to 1000 (default 10).";
modparam dummy numTimersIec "IEC timers %TM, 0 to 10000 (default 10).";
modparam dummy numErrorBits "Error bits %E, 0 to 10000 (default 10).";
option singleton yes;
license "GPL";
author "OpenEMC";
see_also "classicladder(1)";
description """The module holds the PLC: every array the scan uses (rungs, variables,
timers, counters, compiled expressions, sections) lives in one shared memory segment
sized from the module parameters when the module loads. The program comes from a
ClassicLadder project file (.clp) loaded by the user-space loader, usually from a HAL file:

  loadrt classicladder_rt numPhysInputs=8 numPhysOutputs=8
  addf classicladder.0.refresh servo-thread
  loadusr -w classicladder --nogui myladder.clp

Until a project is loaded the scan does nothing and plc-stopped is TRUE. Loading again
replaces the program and clears the memory variables, outputs and element states; a
project with an error is refused (file, line and problem are printed) and the running
program stays.

Pins (NN counts from 00):
  classicladder.0.in-NN        bit in     %I inputs
  classicladder.0.out-NN       bit out    %Q outputs
  classicladder.0.s32in-NN     s32 in     %IW word inputs
  classicladder.0.s32out-NN    s32 out    %QW word outputs
  classicladder.0.floatin-NN   float in   %IF inputs (expressions use the integer part)
  classicladder.0.floatout-NN  float out  %QF outputs
  classicladder.0.hide_gui     bit in     accepted for compatibility (there is no GUI)
  classicladder.0.plc-stopped  bit out    TRUE while no project runs

Function classicladder.0.refresh (floating point) is one PLC scan: it reads the input
pins, evaluates every main section (rungs column by column, following jumps and
subroutine calls) and writes the output pins. Timers advance by the thread period.

Supported elements: contacts (normally open, normally closed, rising and falling edge),
coils (normal, inverted, set, reset), jump, call of a subroutine section, classic timers,
monostables, counters, IEC timers (TON, TOF, TP), compare and operate blocks with
integer expressions (+ - * / %, & | ^, comparisons, ABS MINI MAXI MOY POW) over %B %W
%I %Q %IW %QW %IF %QF %E and timer, monostable and counter fields. Sequential (grafcet)
sections, indexed variables, Modbus and the editor are not provided.""";
