/**
 * For backends only (the simulator and robot-link): the port every student API object delegates
 * to. It lies below the student API and speaks in its own types (booleans for the gripper, a
 * {@link org.kheperasim.api.spi.Mount} for a sensor's place, a map for the run's parameters), so
 * that the student API uses it and it uses nothing of the student API. Students never need it.
 */
package org.kheperasim.api.spi;
