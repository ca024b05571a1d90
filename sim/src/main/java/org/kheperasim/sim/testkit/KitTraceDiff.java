package org.kheperasim.sim.testkit;

import java.util.List;

/**
 * Where two traces differ.
 *
 * @param header the header lines that differ, described
 * @param firstSample the first sample that differs, described, or null when none does
 * @param samples how many samples were compared
 */
public record KitTraceDiff(List<String> header, String firstSample, int samples) {
}
