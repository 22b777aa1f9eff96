#include "engine/haptics/UdpSocket.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

namespace hemiroll::haptics {

namespace {

sockaddr_in toSockaddr(const UdpEndpoint& e) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(e.address);
  a.sin_port = htons(e.port);
  return a;
}

}  // namespace

bool parseIpv4(const std::string& text, std::uint32_t& address) {
  in_addr a{};
  if (inet_pton(AF_INET, text.c_str(), &a) != 1) return false;
  address = ntohl(a.s_addr);
  return true;
}

std::string formatEndpoint(const UdpEndpoint& e) {
  return std::to_string(e.address >> 24) + "." + std::to_string((e.address >> 16) & 0xFF) + "." +
         std::to_string((e.address >> 8) & 0xFF) + "." + std::to_string(e.address & 0xFF) + ":" +
         std::to_string(e.port);
}

std::string UdpSocket::bind(const UdpEndpoint& local) {
  close();
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) return std::string("cannot create a UDP socket: ") + std::strerror(errno);
  const sockaddr_in a = toSockaddr(local);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    const int e = errno;
    close();
    return "cannot bind UDP " + formatEndpoint(local) + ": " + std::strerror(e);
  }
  sockaddr_in bound{};
  socklen_t len = sizeof bound;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&bound), &len);
  localPort_ = ntohs(bound.sin_port);
  return {};
}

void UdpSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  localPort_ = 0;
}

bool UdpSocket::send(const std::uint8_t* data, std::size_t length, const UdpEndpoint& to) const {
  if (fd_ < 0) return false;
  const sockaddr_in a = toSockaddr(to);
  const ssize_t n =
      ::sendto(fd_, data, length, MSG_DONTWAIT | MSG_NOSIGNAL, reinterpret_cast<const sockaddr*>(&a), sizeof a);
  return n == static_cast<ssize_t>(length);
}

long UdpSocket::receive(std::uint8_t* buffer, std::size_t capacity, UdpEndpoint& from,
                        std::int64_t timeoutNs) const {
  if (fd_ < 0) return -1;
  pollfd p{fd_, POLLIN, 0};
  const timespec ts{static_cast<time_t>(timeoutNs / 1'000'000'000), static_cast<long>(timeoutNs % 1'000'000'000)};
  const int ready = ::ppoll(&p, 1, &ts, nullptr);
  if (ready == 0 || (ready < 0 && errno == EINTR)) return 0;
  if (ready < 0) return -1;
  sockaddr_in a{};
  socklen_t len = sizeof a;
  // MSG_TRUNC: the real length comes back even when it exceeds the buffer.
  const ssize_t n = ::recvfrom(fd_, buffer, capacity, MSG_DONTWAIT | MSG_TRUNC, reinterpret_cast<sockaddr*>(&a), &len);
  if (n < 0) return (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) ? 0 : -1;
  from.address = ntohl(a.sin_addr.s_addr);
  from.port = ntohs(a.sin_port);
  return static_cast<std::size_t>(n) > capacity ? static_cast<long>(capacity) + 1 : static_cast<long>(n);
}

}  // namespace hemiroll::haptics
