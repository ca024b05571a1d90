package org.kheperasim.testing;

/**
 * What a robot's body touched. {@link KheperaAssertions} has each as a constant, so a test reads
 * {@code assertThat(run).neverTouched(WALL)}.
 */
public enum Obstacle {
    /** A wall of the arena, or its edge. */
    WALL,
    /** A lamp's body. */
    LAMP,
    /** Another robot. */
    ROBOT,
    /** A bottle cap (pushed, or too heavy to push). */
    CAP;

    /** @return the word a message uses: {@code a wall}, {@code a lamp}, {@code another robot}, {@code a cap} */
    public String described() {
        return switch (this) {
            case WALL -> "a wall";
            case LAMP -> "a lamp";
            case ROBOT -> "another robot";
            case CAP -> "a cap";
        };
    }
}
