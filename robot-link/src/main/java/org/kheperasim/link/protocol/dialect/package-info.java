/**
 * Robots' serial dialects: the Khepera I ({@code khepera1}, the default), the Khepera II
 * ({@code khepera2}) and the e-puck ({@code epuck}), each a {@link
 * org.kheperasim.link.protocol.dialect.Dialect} found by name. A dialect maps what a controller
 * needs to its robot's commands and parses both ways; it never converts units.
 */
package org.kheperasim.link.protocol.dialect;
