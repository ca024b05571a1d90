/**
 * What the two command-line tools ({@code khepera-sim} and {@code khepera-link}) share, so they
 * behave alike: the version string, the exit-code table, the error prefix, number converters that
 * refuse what is not a plain decimal, and the {@code --controller/--classpath/--seconds} options.
 * The simulator depends on robot-link, so both reach it without a cycle.
 */
package org.kheperasim.link.tool;
