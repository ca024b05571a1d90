/**
 * For backends only (the simulator and robot-link): the port every API object delegates to, and
 * the controller contract as code. Students never need this package.
 */
package org.kheperasim.api.spi;
