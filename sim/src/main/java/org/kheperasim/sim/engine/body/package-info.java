/**
 * A robot's body and how it moves: the wheels with their motor period, acceleration and encoders ({@code Wheels}),
 * the disc driven along its arcs and stopped by what it meets ({@code DriveBody}, {@code BodyClearance},
 * {@code CapContacts}), the position controller of the {@code P} command, and the gripper turret's arm and fingers.
 */
package org.kheperasim.sim.engine.body;
