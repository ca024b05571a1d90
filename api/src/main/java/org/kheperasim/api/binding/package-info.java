/**
 * For backends only (the simulator and robot-link): the controller contract as code. It checks a
 * student's class, constructs it bound to a robot's state and drives it (a {@code Controller}
 * thread, a {@code StepController} stepped by a {@link org.kheperasim.api.binding.StepRunner}, or a
 * class of another {@link org.kheperasim.api.binding.ControllerStyle} such as WSU's). It sits above
 * both the student API and the port ({@code api.spi}); students never need it.
 */
package org.kheperasim.api.binding;
