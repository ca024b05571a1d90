package org.kheperasim.link.robot;

/**
 * What one poll cycle saw, with the speeds in force.
 *
 * @param nanos time since polling started, ns
 * @param proximity the eight proximity values
 * @param light the eight ambient-light values
 * @param leftPosition left position counter, pulses
 * @param rightPosition right position counter, pulses
 * @param leftSpeed left speed last sent, units
 * @param rightSpeed right speed last sent, units
 */
public record Sample(long nanos, int[] proximity, int[] light, int leftPosition, int rightPosition,
        int leftSpeed, int rightSpeed) {
}
